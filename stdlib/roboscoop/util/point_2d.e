note
	description: "A point of the plane (metres)."

class
	POINT_2D

inherit
	ANY
		redefine
			out
		end

create
	make

feature {NONE} -- Initialization

	make (a_x, a_y: REAL_64)
			-- Point (`a_x', `a_y').
		do
			x := a_x
			y := a_y
		end

feature -- Access

	x, y: REAL_64
			-- Coordinates.

	distance (other: POINT_2D): REAL_64
			-- Euclidean distance to `other'.
		do
			Result := (other - Current).length
		end

	minus alias "-" (other: POINT_2D): VECTOR_2D
			-- Vector from `other' to Current.
		do
			create Result.make (x - other.x, y - other.y)
		end

	translated (v: VECTOR_2D): POINT_2D
			-- Current moved by `v'.
		do
			create Result.make (x + v.x, y + v.y)
		end

	out: STRING
			-- "(x, y)".
		do
			Result := "(" + x.out + ", " + y.out + ")"
		end

end
