class
	CELSIUS_NOT_A_CREATION_PROCEDURE

create
	make,
	from_integer,
	from_pair

convert
	from_integer ({INTEGER}),
	to_real: {REAL_64},
	scale ({INTEGER_64}) -- E: VNCP

feature {NONE} -- Initialization

	make (d: REAL_64)
			-- Set `degrees' to `d'.
		do
			degrees := d
		end

	from_integer (d: INTEGER)
			-- Set `degrees' to `d'.
		do
			degrees := d
		end

	from_pair (a, b: INTEGER)
			-- Set `degrees' to `a' + `b'.
		do
			degrees := a + b
		end

feature -- Access

	degrees: REAL_64
			-- Temperature.

	to_real: REAL_64
			-- `degrees'.
		do
			Result := degrees
		end

	to_double: REAL_64
			-- `degrees' again.
		do
			Result := degrees
		end

	to_label: STRING
			-- `degrees' as text.
		do
			Result := degrees.out
		end

feature -- Element change

	reset
			-- Set `degrees' to zero.
		do
			degrees := 0
		end

	scale (f: INTEGER_64)
			-- Multiply `degrees' by `f'.
		do
			degrees := degrees * f
		end

end
