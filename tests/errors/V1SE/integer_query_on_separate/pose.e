note
	description: "A position in the plane."

class
	POSE

create
	make

feature {NONE} -- Initialization

	make (a_x, a_y: REAL_64)
			-- Position (`a_x', `a_y').
		do
			x := a_x
			y := a_y
		end

feature -- Access

	x: REAL_64
			-- Horizontal coordinate.

	y: REAL_64
			-- Vertical coordinate.

end
