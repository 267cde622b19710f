note
	description: "Unsigned integers on 8 bits (0 to 255); arithmetic wraps around on overflow."
	implementation: "Every operation is `external %"built_in%"': the code generator maps it onto Python."

frozen expanded class
	NATURAL_8

inherit
	NUMERIC
		rename
			quotient as integer_quotient alias "//",
			opposite as unapplicable_opposite
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
	to_natural_16: {NATURAL_16},
	to_natural_32: {NATURAL_32},
	to_natural_64: {NATURAL_64},
	to_integer_16: {INTEGER_16},
	to_integer_32: {INTEGER_32},
	to_integer_64: {INTEGER_64},
	to_real_32: {REAL_32},
	to_real_64: {REAL_64}

feature -- Access

	item: NATURAL_8
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

	one: NATURAL_8
			-- The value 1.
		external
			"built_in"
		end

	zero: NATURAL_8
			-- The value 0.
		external
			"built_in"
		end

	Min_value: NATURAL_8 = 0
			-- Smallest value of the type.

	Max_value: NATURAL_8 = 255
			-- Largest value of the type.

feature -- Comparison

	is_less alias "<" (other: NATURAL_8): BOOLEAN
			-- Is the current value less than `other'?
		external
			"built_in"
		end

	is_less_equal alias "<=" (other: NATURAL_8): BOOLEAN
			-- Is the current value less than or equal to `other'?
		external
			"built_in"
		end

	is_greater alias ">" (other: NATURAL_8): BOOLEAN
			-- Is the current value greater than `other'?
		external
			"built_in"
		end

	is_greater_equal alias ">=" (other: NATURAL_8): BOOLEAN
			-- Is the current value greater than or equal to `other'?
		external
			"built_in"
		end

	is_equal (other: NATURAL_8): BOOLEAN
			-- Is `other' the same value?
		external
			"built_in"
		end

	three_way_comparison (other: NATURAL_8): INTEGER_32
			-- -1, 0 or 1 as the current value is less than, equal to or greater than `other'.
		external
			"built_in"
		end

	max (other: NATURAL_8): NATURAL_8
			-- The greater of the current value and `other'.
		external
			"built_in"
		end

	min (other: NATURAL_8): NATURAL_8
			-- The smaller of the current value and `other'.
		external
			"built_in"
		end

feature -- Status report

	divisible (other: NATURAL_8): BOOLEAN
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

	is_valid_character_8_code: BOOLEAN
			-- Is the current value a valid CHARACTER_8 code (0 to 255)?
		external
			"built_in"
		end

	is_valid_character_32_code: BOOLEAN
			-- Is the current value a valid CHARACTER_32 code?
		external
			"built_in"
		end

feature -- Basic operations

	plus alias "+" (other: NATURAL_8): NATURAL_8
			-- Sum with `other'.
		external
			"built_in"
		end

	minus alias "-" (other: NATURAL_8): NATURAL_8
			-- Result of subtracting `other'.
		external
			"built_in"
		end

	product alias "*" (other: NATURAL_8): NATURAL_8
			-- Product by `other'.
		external
			"built_in"
		end

	quotient alias "/" (other: NATURAL_8): REAL_64
			-- Division by `other', as a REAL_64.
		require
			good_divisor: divisible (other)
		external
			"built_in"
		end

	identity alias "+": NATURAL_8
			-- Unary plus.
		external
			"built_in"
		end

	unapplicable_opposite: NATURAL_8
			-- Unary minus does not apply to unsigned integers.
		external
			"built_in"
		end

	integer_quotient alias "//" (other: NATURAL_8): NATURAL_8
			-- Integer division of the current value by `other' (rounded toward zero).
		external
			"built_in"
		end

	integer_remainder alias "\\" (other: NATURAL_8): NATURAL_8
			-- Remainder of the integer division by `other' (same sign as the current value).
		require
			good_divisor: divisible (other)
		external
			"built_in"
		end

	power alias "^" (other: REAL_64): REAL_64
			-- The current value raised to the power `other'.
		external
			"built_in"
		end

	interval alias "|..|" (other: INTEGER_32): INTEGER_INTERVAL
			-- Interval from the current value to `other' (empty if `other' is smaller).
		external
			"built_in"
		end

feature -- Conversion

	to_boolean: BOOLEAN
			-- Is the current value non-zero?
		external
			"built_in"
		end

	as_natural_8: NATURAL_8
			-- The current value as a NATURAL_8, keeping the low-order bits.
		external
			"built_in"
		end

	as_natural_16: NATURAL_16
			-- The current value as a NATURAL_16, keeping the low-order bits.
		external
			"built_in"
		end

	as_natural_32: NATURAL_32
			-- The current value as a NATURAL_32, keeping the low-order bits.
		external
			"built_in"
		end

	as_natural_64: NATURAL_64
			-- The current value as a NATURAL_64, keeping the low-order bits.
		external
			"built_in"
		end

	as_integer_8: INTEGER_8
			-- The current value as a INTEGER_8, keeping the low-order bits.
		external
			"built_in"
		end

	as_integer_16: INTEGER_16
			-- The current value as a INTEGER_16, keeping the low-order bits.
		external
			"built_in"
		end

	as_integer_32: INTEGER_32
			-- The current value as a INTEGER_32, keeping the low-order bits.
		external
			"built_in"
		end

	as_integer_64: INTEGER_64
			-- The current value as a INTEGER_64, keeping the low-order bits.
		external
			"built_in"
		end

	to_natural_8: NATURAL_8
			-- The current value as a NATURAL_8.
		external
			"built_in"
		end

	to_natural_16: NATURAL_16
			-- The current value as a NATURAL_16.
		external
			"built_in"
		end

	to_natural_32: NATURAL_32
			-- The current value as a NATURAL_32.
		external
			"built_in"
		end

	to_natural_64: NATURAL_64
			-- The current value as a NATURAL_64.
		external
			"built_in"
		end

	to_integer_8: INTEGER_8
			-- The current value as a INTEGER_8.
		require
			not_too_big: Current <= 127
		external
			"built_in"
		end

	to_integer_16: INTEGER_16
			-- The current value as a INTEGER_16.
		external
			"built_in"
		end

	to_integer_32: INTEGER_32
			-- The current value as a INTEGER_32.
		external
			"built_in"
		end

	to_integer_64: INTEGER_64
			-- The current value as a INTEGER_64.
		external
			"built_in"
		end

	to_real, to_real_32: REAL_32
			-- The current value as a REAL_32 (rounded if needed).
		external
			"built_in"
		end

	to_double, to_real_64: REAL_64
			-- The current value as a REAL_64.
		external
			"built_in"
		end

	to_character_8: CHARACTER_8
			-- The CHARACTER_8 whose code is the current value.
		require
			valid_character: is_valid_character_8_code
		external
			"built_in"
		end

	to_character_32: CHARACTER_32
			-- The CHARACTER_32 whose code is the current value.
		require
			valid_character: is_valid_character_32_code
		external
			"built_in"
		end

	to_hex_string: STRING_8
			-- Hexadecimal representation on 2 digits.
		external
			"built_in"
		end

	to_hex_character: CHARACTER_8
			-- Hexadecimal digit of the current value.
		require
			in_bounds: Current <= 15
		external
			"built_in"
		end

feature -- Bit operations

	bit_and alias "&" (i: NATURAL_8): NATURAL_8
			-- Bitwise and with `i'.
		external
			"built_in"
		end

	bit_or alias "|" (i: NATURAL_8): NATURAL_8
			-- Bitwise or with `i'.
		external
			"built_in"
		end

	bit_xor (i: NATURAL_8): NATURAL_8
			-- Bitwise exclusive or with `i'.
		external
			"built_in"
		end

	bit_not: NATURAL_8
			-- One's complement.
		external
			"built_in"
		end

	bit_shift (n: INTEGER_32): NATURAL_8
			-- Shifted `n' positions right if `n' is positive, left otherwise.
		require
			n_less_or_equal_to_8: n <= 8
			n_greater_or_equal_to_minus_8: n >= -8
		external
			"built_in"
		end

	bit_shift_left alias "|<<" (n: INTEGER_32): NATURAL_8
			-- Shifted `n' positions left.
		require
			n_nonnegative: n >= 0
			n_less_or_equal_to_8: n <= 8
		external
			"built_in"
		end

	bit_shift_right alias "|>>" (n: INTEGER_32): NATURAL_8
			-- Shifted `n' positions right.
		require
			n_nonnegative: n >= 0
			n_less_or_equal_to_8: n <= 8
		external
			"built_in"
		end

	bit_test (n: INTEGER_32): BOOLEAN
			-- Is bit `n' set?
		require
			n_nonnegative: n >= 0
			n_less_than_8: n < 8
		external
			"built_in"
		end

	set_bit (b: BOOLEAN; n: INTEGER_32): NATURAL_8
			-- Copy of the current value with bit `n' set to 1 if `b', to 0 otherwise.
		require
			n_nonnegative: n >= 0
			n_less_than_8: n < 8
		external
			"built_in"
		end

	set_bit_with_mask (b: BOOLEAN; m: NATURAL_8): NATURAL_8
			-- Copy of the current value with the bits of `m' set to 1 if `b', to 0 otherwise.
		external
			"built_in"
		end

feature -- Output

	out: STRING_8
			-- Decimal representation.
		external
			"built_in"
		end

end
