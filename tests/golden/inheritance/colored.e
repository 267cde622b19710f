class
	COLORED

feature -- Access

	color: STRING
		attribute
			Result := "colorless"
		end

	name: STRING
		do
			Result := "colored thing"
		end

	describe: STRING
		do
			Result := color + " " + name
		end

feature -- Change

	set_color (c: STRING)
		do
			color := c
		end

end
