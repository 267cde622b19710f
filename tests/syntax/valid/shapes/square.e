note
	description: "Squares: rectangles whose sides are equal, with a renamed creation procedure."

class
	SQUARE

inherit
	RECTANGLE
		rename
			make as make_rectangle,
			width as side
		export
			{NONE} make_rectangle
		redefine
			name,
			out,
			scale
		end

create
	make

feature {NONE} -- Initialization

	make (s: REAL_64)
			-- Create a square of side `s'.
		require
			s_positive: s > 0.0
		do
			make_rectangle (s, s)
		ensure
			side_set: side = s
		end

feature -- Access

	name: STRING
			-- <Precursor>
		do
			Result := "square"
		end

	out: STRING
			-- Shorter than a rectangle's.
		do
			Result := Precursor {RECTANGLE}
			Result.append (" [side " + side.out + "]")
		end

	scale (factor: REAL_64)
			-- <Precursor>
		require else
			any_factor: factor /= 0.0
		do
			Precursor {RECTANGLE} (factor.abs)
		ensure then
			still_square: side = height
		end

end
