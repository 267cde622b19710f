class
	RECTANGLE

create
	make

feature {NONE} -- Initialization

	make (a_width, a_height: LENGTH)
		do
			width := a_width
			height := a_height
		end

feature -- Access

	width, height: LENGTH

	perimeter: LENGTH
		do
			Result := (width + height) + (width + height)
		end

end
