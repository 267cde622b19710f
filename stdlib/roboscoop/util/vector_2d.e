note
	description: "A vector of the plane."

class
	VECTOR_2D

inherit
	ANY
		redefine
			out
		end

create
	make, make_polar

feature {NONE} -- Initialization

	make (a_x, a_y: REAL_64)
			-- Vector (`a_x', `a_y').
		do
			x := a_x
			y := a_y
		end

	make_polar (a_length, a_angle: REAL_64)
			-- Vector of length `a_length' at angle `a_angle'.
		local
			m: ANGLE_MATH
		do
			create m
			x := a_length * m.cosine (a_angle)
			y := a_length * m.sine (a_angle)
		end

feature -- Access

	x, y: REAL_64
			-- Coordinates.

	length: REAL_64
			-- Euclidean norm.
		do
			Result := (create {ANGLE_MATH}).sqrt (x * x + y * y)
		end

	angle: REAL_64
			-- Direction, in [-pi, pi] (0 for the null vector).
		do
			Result := (create {ANGLE_MATH}).arc_tangent_2 (y, x)
		end

	dot (other: VECTOR_2D): REAL_64
			-- Scalar product.
		do
			Result := x * other.x + y * other.y
		end

	cross (other: VECTOR_2D): REAL_64
			-- z of the cross product.
		do
			Result := x * other.y - y * other.x
		end

	plus alias "+" (other: VECTOR_2D): VECTOR_2D
			-- Sum.
		do
			create Result.make (x + other.x, y + other.y)
		end

	minus alias "-" (other: VECTOR_2D): VECTOR_2D
			-- Difference.
		do
			create Result.make (x - other.x, y - other.y)
		end

	scaled (k: REAL_64): VECTOR_2D
			-- `k' times Current.
		do
			create Result.make (k * x, k * y)
		end

	rotated (a: REAL_64): VECTOR_2D
			-- Current rotated by `a' radians.
		local
			m: ANGLE_MATH
		do
			create m
			create Result.make (x * m.cosine (a) - y * m.sine (a), x * m.sine (a) + y * m.cosine (a))
		end

	out: STRING
			-- "(x, y)".
		do
			Result := "(" + x.out + ", " + y.out + ")"
		end

end
