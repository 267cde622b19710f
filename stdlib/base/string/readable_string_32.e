note
	description: "[
		Read-only interface of strings of 32-bit characters (CHARACTER_32, Unicode),
		with indices 1 to `count'. Iterable: `across s is c loop ... end' visits the characters.
	]"
	implementation: "Externals are provided by the runtime, bound by class and feature name."

deferred class
	READABLE_STRING_32

inherit
	READABLE_STRING_GENERAL
		rename
			same_string as same_string_general,
			starts_with as starts_with_general,
			ends_with as ends_with_general,
			is_case_insensitive_equal as is_case_insensitive_equal_general
		end

	ITERABLE [CHARACTER_32]
		undefine
			is_equal, out, copy
		end

convert
	as_string_8: {READABLE_STRING_8, STRING_8},
	as_string_32: {STRING_32}

feature {NONE} -- Initialization

	make_filled (c: CHARACTER_32; n: INTEGER_32)
			-- Make the string hold `n' copies of `c'.
		require
			valid_count: n >= 0
		external
			"Python"
		end

	make_from_string (s: READABLE_STRING_32)
			-- Make the string hold a copy of the characters of `s'.
		external
			"Python"
		end

	make_from_string_general (s: READABLE_STRING_GENERAL)
			-- Make the string hold a copy of the characters of `s', whatever its type.
		external
			"Python"
		end

	make_from_separate (other: separate READABLE_STRING_GENERAL)
			-- Make the string hold a copy of the characters of `other', which may belong
			-- to another processor.
		external
			"Python"
		end

feature -- Access

	at alias "@" (i: INTEGER_32): CHARACTER_32
			-- Character at position `i'.
		require
			valid_index: valid_index (i)
		do
			Result := item (i)
		end

	item_code (i: INTEGER_32): INTEGER_32
			-- Code of the character at position `i'.
		require
			index_small_enough: i <= count
			index_large_enough: i > 0
		do
			Result := item (i).code
		end

	string: STRING_32
			-- New STRING_32 with the same characters.
		do
			create Result.make_from_string (Current)
		end

	new_cursor: STRING_32_ITERATION_CURSOR
			-- New cursor over the characters, for `across'.
		do
			create Result.make (Current)
		end

feature -- Status report

	is_string_8: BOOLEAN = False
			-- Is the string a sequence of CHARACTER_8? (No.)

	is_string_32: BOOLEAN = True
			-- Is the string a sequence of CHARACTER_32? (Yes.)

	is_valid_as_string_8: BOOLEAN
			-- Are all the characters' codes at most 255?
		external
			"Python"
		end

	valid_code (v: NATURAL_32): BOOLEAN
			-- Is `v' a valid CHARACTER_32 code? (Always.)
		do
			Result := True
		end

	starts_with (s: READABLE_STRING_32): BOOLEAN
			-- Does the string begin with `s'?
		external
			"Python"
		end

	ends_with (s: READABLE_STRING_32): BOOLEAN
			-- Does the string end with `s'?
		external
			"Python"
		end

feature -- Comparison

	same_string (other: READABLE_STRING_32): BOOLEAN
			-- Does `other' have the same characters as the string?
		external
			"Python"
		end

	is_case_insensitive_equal (other: READABLE_STRING_32): BOOLEAN
			-- Does `other' have the same characters as the string, ignoring case?
		external
			"Python"
		end

end
