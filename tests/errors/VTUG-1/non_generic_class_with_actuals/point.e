class
	POINT

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
