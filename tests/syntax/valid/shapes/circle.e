note
	description: "Circles."

class
	CIRCLE

inherit
	SHAPE

	DOUBLE_MATH
		export
			{NONE} all
		undefine
			out
		end

create
	make

feature {NONE} -- Initialization

	make (r: REAL_64)
			-- Create a circle of radius `r'.
		require
			r_positive: r > 0.0
		do
			radius := r
		end

feature -- Access

	radius: REAL_64
			-- Distance from the centre to the border.

	area: REAL_64
		do
			Result := pi * radius ^ 2
		end

	perimeter: REAL_64
		do
			Result := 2 * pi * radius
		end

	name: STRING = "circle"

end
