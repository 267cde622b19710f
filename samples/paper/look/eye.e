note
	description: "An eye of a robot head (a stand-in part): it turns toward a point."

class
	EYE

create
	make

feature {NONE} -- Initialization

	make (a_name: separate STRING; a_offset: REAL_64)
			-- Eye `a_name', `a_offset' metres to the right of the head's centre, looking ahead.
		do
			create name.make_from_separate (a_name)
			offset := a_offset
			create clock.make
		end

feature -- Access

	name: STRING
			-- "Left" or "Right".

	offset: REAL_64
			-- Sideways position on the head (m, right positive).

	direction: REAL_64
			-- Where the eye looks (degrees, left positive; 0 straight ahead).

	move_count: INTEGER
			-- Times the eye moved.

feature -- Basic operations

	look_at (a_x, a_y: REAL_64)
			-- Turn toward the point `a_x' metres ahead, `a_y' metres to the left of the head.
		local
			math: ANGLE_MATH
		do
			create math
			direction := math.degrees (math.arc_tangent_2 (a_y + offset, a_x))
			move_count := move_count + 1
			print (name + " eye at " + clock.now.rounded.out + " s: looks " + direction.rounded.out + " degrees%N")
		ensure
			moved: move_count = old move_count + 1
		end

feature {NONE} -- Implementation

	clock: TIMER
			-- The runtime's clock.

end
