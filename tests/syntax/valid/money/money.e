note
	description: "An amount of money in cents, with operator aliases and conversions."

class
	MONEY

inherit
	COMPARABLE
		redefine
			out
		end

create
	make, make_from_integer

convert
	make_from_integer ({INTEGER}),
	to_real: {REAL_64}

feature {NONE} -- Initialization

	make (a_cents: INTEGER_64)
			-- Create an amount of `a_cents' cents.
		do
			cents := a_cents
		ensure
			cents_set: cents = a_cents
		end

	make_from_integer (a_units: INTEGER)
			-- Create an amount of `a_units' whole units.
		do
			cents := a_units.to_integer_64 * 100
		end

feature -- Access

	cents: INTEGER_64
			-- Value in cents.

feature -- Operations

	plus alias "+" (other: MONEY): MONEY
			-- Sum of Current and `other'.
		do
			create Result.make (cents + other.cents)
		ensure
			sum: Result.cents = cents + other.cents
		end

	minus alias "-" (other: MONEY): MONEY
			-- Difference.
		do
			create Result.make (cents - other.cents)
		end

	negated alias "-": MONEY
			-- The opposite amount.
		do
			create Result.make (- cents)
		end

	identity alias "+": MONEY
			-- The same amount.
		do
			Result := Current
		end

	times alias "*" (factor: INTEGER): MONEY
			-- Current multiplied by `factor'.
		do
			create Result.make (cents * factor)
		end

	share alias "//" (parts: INTEGER): MONEY
			-- One of `parts' equal shares, rounded down.
		require
			parts_positive: parts > 0
		do
			create Result.make (cents // parts)
		end

	remainder alias "\\" (parts: INTEGER): MONEY
			-- What is left after sharing into `parts'.
		require
			parts_positive: parts > 0
		do
			create Result.make (cents \\ parts)
		end

	percent alias "|@|" (rate: INTEGER): MONEY
			-- `rate' percent of Current (a free operator).
		do
			create Result.make (cents * rate // 100)
		end

feature -- Comparison

	is_less alias "<" (other: like Current): BOOLEAN
			-- Is Current less than `other'?
		do
			Result := cents < other.cents
		end

feature -- Conversion

	to_real: REAL_64
			-- Value in units.
		do
			Result := cents / 100
		end

	out: STRING
			-- Printable form.
		do
			Result := (cents // 100).out + "." + (cents \\ 100).out
		end

end
