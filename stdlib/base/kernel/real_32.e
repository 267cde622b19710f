note
	description: "Floating-point numbers on 32 bits (IEEE 754 single precision)."
	implementation: "Every operation is `external %"built_in%"': the code generator maps it onto Python."

frozen expanded class
	REAL_32

inherit
	NUMERIC
		redefine
			is_equal, out
		end

	COMPARABLE
		redefine
			is_equal, out, is_less_equal, is_greater, is_greater_equal, three_way_comparison, max, min
		end

	HASHABLE
		redefine
			is_equal, out, is_hashable
		end

convert
	to_double: {REAL_64}

feature -- Access

	item: REAL_32
			-- The value itself.
		external
			"built_in"
		end

	hash_code: INTEGER_32
			-- Hash code value (non-negative).
		external
			"built_in"
		end

	sign: INTEGER_32
			-- -1, 0 or 1 as the value is negative, zero or positive.
		external
			"built_in"
		end

	one: REAL_32
			-- The value 1.0.
		external
			"built_in"
		end

	zero: REAL_32
			-- The value 0.0.
		external
			"built_in"
		end

	nan: REAL_32
			-- Not a number.
		external
			"built_in"
		end

	negative_infinity: REAL_32
			-- Negative infinity.
		external
			"built_in"
		end

	positive_infinity: REAL_32
			-- Positive infinity.
		external
			"built_in"
		end

	Min_value: REAL_32 = -3.4028234663852885981170e+038
			-- Most negative finite value.

	Max_value: REAL_32 = 3.4028234663852885981170e+038
			-- Largest finite value.

	Epsilon: REAL_32 = 1.1754943508222875079688e-038
			-- Smallest normalized positive value.

	Machine_epsilon: REAL_32 = 1.1920928955078125000000e-007
			-- Difference between 1 and the next representable value.

feature -- Comparison

	is_less alias "<" (other: REAL_32): BOOLEAN
			-- Is the current value less than `other'?
		external
			"built_in"
		end

	is_less_equal alias "<=" (other: REAL_32): BOOLEAN
			-- Is the current value less than or equal to `other'?
		external
			"built_in"
		end

	is_greater alias ">" (other: REAL_32): BOOLEAN
			-- Is the current value greater than `other'?
		external
			"built_in"
		end

	is_greater_equal alias ">=" (other: REAL_32): BOOLEAN
			-- Is the current value greater than or equal to `other'?
		external
			"built_in"
		end

	is_equal (other: REAL_32): BOOLEAN
			-- Is `other' the same value (NaN is equal to NaN)?
		external
			"built_in"
		end

	ieee_is_equal (other: REAL_32): BOOLEAN
			-- Is `other' equal by IEEE 754 rules (NaN equals nothing)?
		external
			"built_in"
		end

	three_way_comparison (other: REAL_32): INTEGER_32
			-- -1, 0 or 1 as the current value is less than, equal to or greater than `other'.
		external
			"built_in"
		end

	max (other: REAL_32): REAL_32
			-- The greater of the current value and `other'.
		external
			"built_in"
		end

	min (other: REAL_32): REAL_32
			-- The smaller of the current value and `other'.
		external
			"built_in"
		end

feature -- Status report

	divisible (other: REAL_32): BOOLEAN
			-- May the current value be divided by `other' (is `other' non-zero)?
		external
			"built_in"
		end

	exponentiable (other: NUMERIC): BOOLEAN
			-- May the current value be raised to the power `other'?
		external
			"built_in"
		end

	is_hashable: BOOLEAN
			-- May the current value be hashed (is it not zero)?
		external
			"built_in"
		end

	is_nan: BOOLEAN
			-- Is the current value not a number?
		external
			"built_in"
		end

	is_negative_infinity: BOOLEAN
			-- Is the current value negative infinity?
		external
			"built_in"
		end

	is_positive_infinity: BOOLEAN
			-- Is the current value positive infinity?
		external
			"built_in"
		end

feature -- Basic operations

	abs: REAL_32
			-- Absolute value.
		external
			"built_in"
		end

	plus alias "+" (other: REAL_32): REAL_32
			-- Sum with `other'.
		external
			"built_in"
		end

	minus alias "-" (other: REAL_32): REAL_32
			-- Result of subtracting `other'.
		external
			"built_in"
		end

	product alias "*" (other: REAL_32): REAL_32
			-- Product by `other'.
		external
			"built_in"
		end

	quotient alias "/" (other: REAL_32): REAL_32
			-- Division by `other'.
		external
			"built_in"
		end

	power alias "^" (other: REAL_64): REAL_64
			-- The current value raised to the power `other'.
		external
			"built_in"
		end

	identity alias "+": REAL_32
			-- Unary plus.
		external
			"built_in"
		end

	opposite alias "-": REAL_32
			-- Unary minus.
		external
			"built_in"
		end

feature -- Conversion

	truncated_to_integer: INTEGER_32
			-- Integer part (rounded toward zero).
		external
			"built_in"
		end

	truncated_to_integer_64: INTEGER_64
			-- Integer part (rounded toward zero), as an INTEGER_64.
		external
			"built_in"
		end

	to_double, to_real_64: REAL_64
			-- The current value as a REAL_64.
		external
			"built_in"
		end

	ceiling: INTEGER_32
			-- Smallest integral value no smaller than the current value.
		external
			"built_in"
		end

	floor: INTEGER_32
			-- Greatest integral value no greater than the current value.
		external
			"built_in"
		end

	rounded: INTEGER_32
			-- Nearest integral value (halves are rounded away from zero).
		external
			"built_in"
		end

	ceiling_real_32: REAL_32
			-- Smallest integral value no smaller than the current value.
		external
			"built_in"
		end

	floor_real_32: REAL_32
			-- Greatest integral value no greater than the current value.
		external
			"built_in"
		end

	rounded_real_32: REAL_32
			-- Nearest integral value (halves are rounded away from zero).
		external
			"built_in"
		end

feature -- Output

	out: STRING_8
			-- Decimal representation, as EiffelStudio prints it.
		external
			"built_in"
		end

end
