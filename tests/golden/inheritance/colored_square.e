class
	COLORED_SQUARE

inherit
	SQUARE
		redefine
			describe
		end

	COLORED
		rename
			describe as color_description
		undefine
			name
		end

create
	make_colored

feature {NONE} -- Initialization

	make_colored (side: REAL_64; c: STRING)
		do
			make (side)
			set_color (c)
		end

feature -- Access

	describe: STRING
		do
			Result := Precursor {SQUARE} + ", " + color_description
		end

end
