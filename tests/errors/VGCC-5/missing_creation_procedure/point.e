class
	POINT

create
	make

feature {NONE} -- Initialization

	make (a_x, a_y: INTEGER)
			-- Create at (`a_x', `a_y').
		do
			x := a_x
			y := a_y
		end

feature -- Access

	x, y: INTEGER
			-- Coordinates.

feature -- Element change

	move (dx, dy: INTEGER)
			-- Move by `dx' and `dy'.
		do
			x := x + dx
			y := y + dy
		end

end
