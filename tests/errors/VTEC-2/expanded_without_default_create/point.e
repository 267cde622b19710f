expanded class
	POINT -- E: VTEC(2)

create
	make

feature {NONE} -- Initialization

	make (a_x, a_y: INTEGER)
			-- The point (`a_x', `a_y').
		do
			x := a_x
			y := a_y
		end

feature -- Access

	x, y: INTEGER
			-- Coordinates.

end
