note
	description: "Rectangles with sides parallel to the axes."

class
	RECTANGLE

inherit
	SHAPE
		redefine
			out
		end

create
	make

feature {NONE} -- Initialization

	make (w, h: REAL_64)
			-- Create a `w' by `h' rectangle.
		require
			w_positive: w > 0.0
			h_positive: h > 0.0
		do
			width := w
			height := h
		ensure
			width_set: width = w
			height_set: height = h
		end

feature -- Access

	width, height: REAL_64
			-- Sides.

	area: REAL_64
			-- <Precursor>
		do
			Result := width * height
		end

	perimeter: REAL_64
			-- <Precursor>
		do
			Result := 2 * (width + height)
		end

	name: STRING
			-- <Precursor>
		do
			Result := "rectangle"
		end

	out: STRING
			-- <Precursor> with the sides.
		do
			Result := Precursor + " (" + width.out + " x " + height.out + ")"
		end

feature -- Transformation

	scale (factor: REAL_64)
			-- Multiply both sides by `factor'.
		require
			factor_positive: factor > 0.0
		do
			width := width * factor
			height := height * factor
		ensure
			area_scaled: (area - old area * factor * factor).abs < 1.0e-9
		end

invariant
	positive_sides: width > 0.0 and height > 0.0

end
