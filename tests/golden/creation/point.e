class
	POINT

inherit
	ANY
		redefine
			default_create,
			out
		end

create
	make,
	make_origin,
	default_create

feature {NONE} -- Initialization

	make (ax, ay: INTEGER)
		do
			x := ax
			y := ay
			creations := creations + 1
		end

	make_origin
		do
		end

	default_create
		do
			x := -1
			y := -1
		end

feature -- Access

	x, y: INTEGER

	creations: INTEGER

	out: STRING
		do
			Result := "(" + x.out + ", " + y.out + ")"
		end

end
