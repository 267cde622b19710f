note
	description: "A position and a heading in the plane."

class
	POSE_2D

inherit
	ANY
		redefine
			out
		end

create
	make

feature {NONE} -- Initialization

	make (a_x, a_y, a_theta: REAL_64)
			-- Pose at (`a_x', `a_y') heading `a_theta' (normalized).
		do
			x := a_x
			y := a_y
			theta := (create {ANGLE_MATH}).normalized_angle (a_theta)
		end

feature -- Access

	x, y, theta: REAL_64
			-- Position and heading (radians, in (-pi, pi]).

	position: POINT_2D
			-- The position.
		do
			create Result.make (x, y)
		end

	heading: VECTOR_2D
			-- Unit vector of the heading.
		do
			create Result.make_polar (1.0, theta)
		end

	distance_to (p: POINT_2D): REAL_64
			-- Distance from the position to `p'.
		do
			Result := position.distance (p)
		end

	bearing_to (p: POINT_2D): REAL_64
			-- Rotation needed to face `p', in (-pi, pi].
		local
			m: ANGLE_MATH
		do
			create m
			Result := m.angle_difference ((p - position).angle, theta)
		end

	out: STRING
			-- "(x, y, theta)".
		do
			Result := "(" + x.out + ", " + y.out + ", " + theta.out + ")"
		end

end
