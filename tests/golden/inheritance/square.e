class
	SQUARE

inherit
	RECTANGLE
		rename
			make as make_rectangle
		redefine
			name
		end

create
	make

feature {NONE} -- Initialization

	make (side: REAL_64)
		do
			make_rectangle (side, side)
		end

feature -- Access

	name: STRING
		do
			Result := "square"
		end

end
