note
	description: "A point in the plane, copied on assignment."

expanded class
	POSITION

feature -- Access

	x: REAL_64
			-- Horizontal coordinate.

	y: REAL_64
			-- Vertical coordinate.

feature -- Element change

	set (a_x, a_y: REAL_64)
			-- Move to (`a_x', `a_y').
		do
			x := a_x
			y := a_y
		end

end
