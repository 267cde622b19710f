note
	description: "An expanded class: points are values, copied on assignment."

expanded class
	POINT

inherit
	ANY
		redefine
			default_create,
			out
		end

create
	default_create, make

feature {NONE} -- Initialization

	default_create
			-- The origin.
		do
			x := 0
			y := 0
		end

	make (a_x, a_y: INTEGER)
			-- The point (`a_x', `a_y').
		do
			x := a_x
			y := a_y
		end

feature -- Access

	x, y: INTEGER
			-- Coordinates.

	translated (dx, dy: INTEGER): POINT
			-- This point moved by (`dx', `dy').
		do
			create Result.make (x + dx, y + dy)
		end

	out: STRING
			-- "(x, y)".
		do
			Result := "(" + x.out + ", " + y.out + ")"
		end

end
