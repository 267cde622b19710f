class
	VECTOR

create
	make

feature {NONE} -- Initialization

	make (a_x, a_y: INTEGER)
			-- A vector (`a_x', `a_y').
		do
			x := a_x
			y := a_y
		end

feature -- Access

	x, y: INTEGER
			-- Coordinates.

feature -- Operations

	opposite alias "-": VECTOR
			-- The opposite vector.
		do
			create Result.make (- x, - y)
		end

	minus alias "-" (other: VECTOR): VECTOR
			-- Difference with `other'.
		do
			create Result.make (x - other.x, y - other.y)
		end

	scale alias "*" (a, b: INTEGER): VECTOR -- E: VFAV(1)
			-- Scaled by `a' / `b'.
		do
			create Result.make (x * a // b, y * a // b)
		end

	reset alias "+" -- E: VFAV(1)
			-- Set to zero.
		do
			x := 0
			y := 0
		end

end
