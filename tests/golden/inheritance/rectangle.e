class
	RECTANGLE

inherit
	SHAPE

create
	make

feature {NONE} -- Initialization

	make (w, h: REAL_64)
		do
			width := w
			height := h
		end

feature -- Access

	width, height: REAL_64

	area: REAL_64
		do
			Result := width * height
		end

	name: STRING
		do
			Result := "rectangle"
		end

end
