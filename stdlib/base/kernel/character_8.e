note
	description: "8-bit characters (codes 0 to 255), ordered by code."
	implementation: "Every operation is `external %"built_in%"': the code generator maps it onto Python."

frozen expanded class
	CHARACTER_8

inherit
	COMPARABLE
		redefine
			is_equal, out, is_less_equal, is_greater, is_greater_equal, three_way_comparison, max, min
		end

	HASHABLE
		redefine
			is_equal, out
		end

convert
	to_character_32: {CHARACTER_32}

feature -- Access

	item: CHARACTER_8
			-- The value itself.
		external
			"built_in"
		end

	code: INTEGER_32
			-- Code of the character.
		external
			"built_in"
		end

	natural_32_code: NATURAL_32
			-- Code of the character, as a NATURAL_32.
		external
			"built_in"
		end

	hash_code: INTEGER_32
			-- Hash code value (the character's code).
		external
			"built_in"
		end

	Min_value: INTEGER_32 = 0
			-- Smallest character code.

	Max_value: INTEGER_32 = 255
			-- Largest character code.

	Max_ascii_value: INTEGER_32 = 127
			-- Largest ASCII character code.

feature -- Comparison

	is_less alias "<" (other: CHARACTER_8): BOOLEAN
			-- Does the current character come before `other' in code order?
		external
			"built_in"
		end

	is_less_equal alias "<=" (other: CHARACTER_8): BOOLEAN
			-- Is the current character's code at most `other''s?
		external
			"built_in"
		end

	is_greater alias ">" (other: CHARACTER_8): BOOLEAN
			-- Does the current character come after `other' in code order?
		external
			"built_in"
		end

	is_greater_equal alias ">=" (other: CHARACTER_8): BOOLEAN
			-- Is the current character's code at least `other''s?
		external
			"built_in"
		end

	is_equal (other: CHARACTER_8): BOOLEAN
			-- Is `other' the same character?
		external
			"built_in"
		end

	three_way_comparison (other: CHARACTER_8): INTEGER_32
			-- -1, 0 or 1 as the current character comes before, is, or comes after `other'.
		external
			"built_in"
		end

	max (other: CHARACTER_8): CHARACTER_8
			-- The greater of the current character and `other'.
		external
			"built_in"
		end

	min (other: CHARACTER_8): CHARACTER_8
			-- The smaller of the current character and `other'.
		external
			"built_in"
		end

feature -- Basic operations

	plus alias "+" (incr: INTEGER_32): CHARACTER_8
			-- The character whose code is `code + incr'.
		require
			valid_increment: (code + incr).is_valid_character_8_code
		external
			"built_in"
		end

	minus alias "-" (decr: INTEGER_32): CHARACTER_8
			-- The character whose code is `code - decr'.
		require
			valid_decrement: (code - decr).is_valid_character_8_code
		external
			"built_in"
		end

	difference alias "|-|" (other: CHARACTER_8): INTEGER_32
			-- Difference of the codes of the current character and `other'.
		external
			"built_in"
		end

	next: CHARACTER_8
			-- The character that follows in code order.
		require
			valid_character: (code + 1).is_valid_character_8_code
		external
			"built_in"
		end

	previous: CHARACTER_8
			-- The character that precedes in code order.
		require
			valid_character: (code - 1).is_valid_character_8_code
		external
			"built_in"
		end

feature -- Conversion

	to_character_8: CHARACTER_8
			-- The character itself.
		external
			"built_in"
		end

	to_character_32: CHARACTER_32
			-- The same character as a CHARACTER_32.
		external
			"built_in"
		end

	as_upper, upper: CHARACTER_8
			-- Upper-case version of the character (the character itself if none).
		external
			"built_in"
		end

	as_lower, lower: CHARACTER_8
			-- Lower-case version of the character (the character itself if none).
		external
			"built_in"
		end

	to_hexa_digit: NATURAL_8
			-- Value of the character as a hexadecimal digit.
		require
			is_hexa_digit: is_hexa_digit
		external
			"built_in"
		end

feature -- Status report

	is_alpha: BOOLEAN
			-- Is the character a letter?
		external
			"built_in"
		end

	is_upper: BOOLEAN
			-- Is the character an upper-case letter?
		external
			"built_in"
		end

	is_lower: BOOLEAN
			-- Is the character a lower-case letter?
		external
			"built_in"
		end

	is_digit: BOOLEAN
			-- Is the character a decimal digit?
		external
			"built_in"
		end

	is_hexa_digit: BOOLEAN
			-- Is the character a hexadecimal digit (0-9, a-f, A-F)?
		external
			"built_in"
		end

	is_space: BOOLEAN
			-- Is the character white space?
		external
			"built_in"
		end

	is_punctuation: BOOLEAN
			-- Is the character a punctuation mark?
		external
			"built_in"
		end

	is_alpha_numeric: BOOLEAN
			-- Is the character a letter or a digit?
		external
			"built_in"
		end

	is_printable: BOOLEAN
			-- Is the character printable (including the space)?
		external
			"built_in"
		end

	is_graph: BOOLEAN
			-- Is the character printable and not a space?
		external
			"built_in"
		end

	is_control: BOOLEAN
			-- Is the character a control character?
		external
			"built_in"
		end

feature -- Output

	out: STRING_8
			-- A string holding the character.
		external
			"built_in"
		end

end
