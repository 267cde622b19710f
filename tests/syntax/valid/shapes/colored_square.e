note
	description: "Squares with a colour: repeated inheritance of `out' resolved with rename, undefine and select."

class
	COLORED_SQUARE

inherit
	SQUARE
		rename
			make as make_square
		undefine
			is_equal
		redefine
			name
		select
			out
		end

	COLORED
		rename
			out as color_out
		undefine
			name,
			is_equal
		redefine
			color_out
		end

	COMPARABLE
		undefine
			out
		end

create
	make

feature {NONE} -- Initialization

	make (s: REAL_64; c: STRING)
			-- Create a square of side `s' and colour `c'.
		do
			make_square (s)
			color := c
		end

feature -- Access

	color: STRING
			-- <Precursor>

	name: STRING
			-- <Precursor>
		do
			Result := color + " " + Precursor {SQUARE}
		end

	color_out: STRING
			-- <Precursor>
		do
			Result := "colour " + Precursor
		end

feature -- Comparison

	is_less alias "<" (other: like Current): BOOLEAN
			-- Is Current smaller than `other'?
		do
			Result := area < other.area
		end

end
