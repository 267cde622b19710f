note
	description: "Floating-point numbers on 64 bits (IEEE 754 double precision)."
	implementation: "Every operation is `external %"built_in%"': the code generator maps it onto Python."

frozen expanded class
	REAL_64

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

feature -- Access

	item: REAL_64
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

	one: REAL_64
			-- The value 1.0.
		external
			"built_in"
		end

	zero: REAL_64
			-- The value 0.0.
		external
			"built_in"
		end

	nan: REAL_64
			-- Not a number.
		external
			"built_in"
		end

	negative_infinity: REAL_64
			-- Negative infinity.
		external
			"built_in"
		end

	positive_infinity: REAL_64
			-- Positive infinity.
		external
			"built_in"
		end

	Min_value: REAL_64 = -1.7976931348623157081452e+308
			-- Most negative finite value.

	Max_value: REAL_64 = 1.7976931348623157081452e+308
			-- Largest finite value.

	Epsilon: REAL_64 = 2.2250738585072013830903e-308
			-- Smallest normalized positive value.

	Machine_epsilon: REAL_64 = 2.2204460492503130808473e-016
			-- Difference between 1 and the next representable value.

feature -- Comparison

	is_less alias "<" (other: REAL_64): BOOLEAN
			-- Is the current value less than `other'?
		external
			"built_in"
		end

	is_less_equal alias "<=" (other: REAL_64): BOOLEAN
			-- Is the current value less than or equal to `other'?
		external
			"built_in"
		end

	is_greater alias ">" (other: REAL_64): BOOLEAN
			-- Is the current value greater than `other'?
		external
			"built_in"
		end

	is_greater_equal alias ">=" (other: REAL_64): BOOLEAN
			-- Is the current value greater than or equal to `other'?
		external
			"built_in"
		end

	is_equal (other: REAL_64): BOOLEAN
			-- Is `other' the same value (NaN is equal to NaN)?
		external
			"built_in"
		end

	ieee_is_equal (other: REAL_64): BOOLEAN
			-- Is `other' equal by IEEE 754 rules (NaN equals nothing)?
		external
			"built_in"
		end

	three_way_comparison (other: REAL_64): INTEGER_32
			-- -1, 0 or 1 as the current value is less than, equal to or greater than `other'.
		external
			"built_in"
		end

	max (other: REAL_64): REAL_64
			-- The greater of the current value and `other'.
		external
			"built_in"
		end

	min (other: REAL_64): REAL_64
			-- The smaller of the current value and `other'.
		external
			"built_in"
		end

feature -- Status report

	divisible (other: REAL_64): BOOLEAN
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

	abs: REAL_64
			-- Absolute value.
		external
			"built_in"
		end

	plus alias "+" (other: REAL_64): REAL_64
			-- Sum with `other'.
		external
			"built_in"
		end

	minus alias "-" (other: REAL_64): REAL_64
			-- Result of subtracting `other'.
		external
			"built_in"
		end

	product alias "*" (other: REAL_64): REAL_64
			-- Product by `other'.
		external
			"built_in"
		end

	quotient alias "/" (other: REAL_64): REAL_64
			-- Division by `other'.
		external
			"built_in"
		end

	power alias "^" (other: REAL_64): REAL_64
			-- The current value raised to the power `other'.
		external
			"built_in"
		end

	identity alias "+": REAL_64
			-- Unary plus.
		external
			"built_in"
		end

	opposite alias "-": REAL_64
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

	truncated_to_real: REAL_32
			-- The current value rounded to a REAL_32.
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

	ceiling_real_64: REAL_64
			-- Smallest integral value no smaller than the current value.
		external
			"built_in"
		end

	floor_real_64: REAL_64
			-- Greatest integral value no greater than the current value.
		external
			"built_in"
		end

	rounded_real_64: REAL_64
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
