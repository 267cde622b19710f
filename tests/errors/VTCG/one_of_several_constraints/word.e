class
	WORD

inherit
	PRINTABLE

	SIZED

create
	make

feature {NONE} -- Initialization

	make
			-- A word of two letters.
		do
			image := "ab"
		end

feature -- Access

	image: STRING

	size: INTEGER
		do
			Result := image.count
		end

end
