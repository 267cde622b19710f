class
	CELSIUS

inherit
	ANY
		redefine
			out
		end

create
	make,
	from_integer

convert
	from_integer ({INTEGER}),
	to_kelvin: {REAL_64}

feature {NONE} -- Initialization

	make (d: REAL_64)
		do
			degrees := d
		end

	from_integer (d: INTEGER)
		do
			degrees := d
		end

feature -- Access

	degrees: REAL_64

	to_kelvin: REAL_64
		do
			Result := degrees + 273.15
		end

	out: STRING
		do
			Result := degrees.out + " C"
		end

end
