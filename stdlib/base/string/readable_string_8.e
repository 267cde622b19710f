note
	description: "[
		Read-only interface of strings of 8-bit characters (CHARACTER_8), with
		indices 1 to `count'. Iterable: `across s is c loop ... end' visits the characters.
	]"
	implementation: "[
		The general features that take or give CHARACTER_32 are renamed (`character_32_item',
		`character_32_has', ...), as in EiffelBase, so that `item', `has', `index_of' and
		`occurrences' work on CHARACTER_8. Externals are provided by the runtime.
	]"

deferred class
	READABLE_STRING_8

inherit
	READABLE_STRING_GENERAL
		rename
			same_string as same_string_general,
			starts_with as starts_with_general,
			ends_with as ends_with_general,
			is_case_insensitive_equal as is_case_insensitive_equal_general,
			item as character_32_item,
			has as character_32_has,
			index_of as character_32_index_of,
			last_index_of as character_32_last_index_of,
			occurrences as character_32_occurrences
		end

	ITERABLE [CHARACTER_8]
		undefine
			is_equal, out, copy
		end

convert
	as_string_8: {STRING_8},
	as_string_32: {READABLE_STRING_32, STRING_32}

feature {NONE} -- Initialization

	make_filled (c: CHARACTER_8; n: INTEGER_32)
			-- Make the string hold `n' copies of `c'.
		require
			valid_count: n >= 0
		external
			"Python"
		end

	make_from_string (s: READABLE_STRING_8)
			-- Make the string hold a copy of the characters of `s'.
		external
			"Python"
		end

	make_from_separate (other: separate READABLE_STRING_8)
			-- Make the string hold a copy of the characters of `other', which may belong
			-- to another processor.
		external
			"Python"
		end

feature -- Access

	item alias "[]" (i: INTEGER_32): CHARACTER_8
			-- Character at position `i'.
		require
			valid_index: valid_index (i)
		deferred
		end

	at alias "@" (i: INTEGER_32): CHARACTER_8
			-- Character at position `i'.
		require
			valid_index: valid_index (i)
		do
			Result := item (i)
		end

	character_32_item (i: INTEGER_32): CHARACTER_32
			-- Character at position `i', as a CHARACTER_32.
		external
			"Python"
		end

	item_code (i: INTEGER_32): INTEGER_32
			-- Code of the character at position `i'.
		require
			index_small_enough: i <= count
			index_large_enough: i > 0
		do
			Result := item (i).code
		end

	index_of (c: CHARACTER_8; start_index: INTEGER_32): INTEGER_32
			-- Position of the first occurrence of `c' at or after `start_index'; 0 if none.
		require
			start_large_enough: start_index >= 1
			start_small_enough: start_index <= count + 1
		external
			"Python"
		end

	last_index_of (c: CHARACTER_8; start_index_from_end: INTEGER_32): INTEGER_32
			-- Position of the last occurrence of `c' at or before `start_index_from_end'; 0 if none.
		require
			start_index_small_enough: start_index_from_end <= count
			start_index_large_enough: start_index_from_end >= 1
		external
			"Python"
		end

	string: STRING_8
			-- New STRING_8 with the same characters.
		do
			create Result.make_from_string (Current)
		end

	new_cursor: STRING_8_ITERATION_CURSOR
			-- New cursor over the characters, for `across'.
		do
			create Result.make (Current)
		end

feature -- Measurement

	occurrences (c: CHARACTER_8): INTEGER_32
			-- Number of times `c' appears in the string.
		external
			"Python"
		end

feature -- Status report

	is_string_8: BOOLEAN = True
			-- Is the string a sequence of CHARACTER_8? (Yes.)

	is_string_32: BOOLEAN = False
			-- Is the string a sequence of CHARACTER_32? (No.)

	is_valid_as_string_8: BOOLEAN = True
			-- Can the string be converted to a STRING_8 without loss? (Yes.)

	valid_code (v: NATURAL_32): BOOLEAN
			-- Is `v' a valid CHARACTER_8 code (0 to 255)?
		do
			Result := v <= 255
		end

	has (c: CHARACTER_8): BOOLEAN
			-- Does the string contain `c'?
		external
			"Python"
		end

	starts_with (s: READABLE_STRING_8): BOOLEAN
			-- Does the string begin with `s'?
		external
			"Python"
		end

	ends_with (s: READABLE_STRING_8): BOOLEAN
			-- Does the string end with `s'?
		external
			"Python"
		end

feature -- Comparison

	same_string (other: READABLE_STRING_8): BOOLEAN
			-- Does `other' have the same characters as the string?
		external
			"Python"
		end

	is_case_insensitive_equal (other: READABLE_STRING_8): BOOLEAN
			-- Does `other' have the same characters as the string, ignoring case?
		external
			"Python"
		end

end
