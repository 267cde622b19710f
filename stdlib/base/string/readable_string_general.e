note
	description: "[
		Read-only interface common to every string: sequences of characters with
		indices 1 to `count'. Characters are seen as CHARACTER_32 here; READABLE_STRING_8
		and READABLE_STRING_32 give the typed views.
	]"
	implementation: "[
		The characters live in the host (Python): features marked `external "Python"'
		are provided by the runtime for every string class, bound by this class's
		name and the feature's name as written here. Features with Eiffel bodies are
		written in terms of those.
	]"

deferred class
	READABLE_STRING_GENERAL

inherit
	COMPARABLE
		redefine
			is_equal, out, copy
		end

	HASHABLE
		redefine
			is_equal, out, copy
		end

feature {NONE} -- Initialization

	make (n: INTEGER_32)
			-- Make the string empty, with room for at least `n' characters.
		require
			non_negative_size: n >= 0
		external
			"Python"
		end

	make_empty
			-- Make the string empty.
		do
			make (0)
		end

feature -- Access

	item alias "[]" (i: INTEGER_32): CHARACTER_32
			-- Character at position `i'.
		require
			valid_index: valid_index (i)
		deferred
		end

	code (i: INTEGER_32): NATURAL_32
			-- Code of the character at position `i'.
		require
			valid_index: valid_index (i)
		external
			"Python"
		end

	index_of (c: CHARACTER_32; start_index: INTEGER_32): INTEGER_32
			-- Position of the first occurrence of `c' at or after `start_index'; 0 if none.
		require
			start_large_enough: start_index >= 1
			start_small_enough: start_index <= count + 1
		external
			"Python"
		end

	last_index_of (c: CHARACTER_32; start_index_from_end: INTEGER_32): INTEGER_32
			-- Position of the last occurrence of `c' at or before `start_index_from_end'; 0 if none.
		require
			start_index_small_enough: start_index_from_end <= count
			start_index_large_enough: start_index_from_end >= 1
		external
			"Python"
		end

	substring_index (other: READABLE_STRING_GENERAL; start_index: INTEGER_32): INTEGER_32
			-- Position of the first occurrence of `other' at or after `start_index'; 0 if none.
		require
			valid_start_index: start_index >= 1 and start_index <= count + 1
		external
			"Python"
		end

	substring_index_in_bounds (other: READABLE_STRING_GENERAL; start_pos, end_pos: INTEGER_32): INTEGER_32
			-- Position of the first occurrence of `other' within `start_pos'..`end_pos'; 0 if none.
		require
			other_not_empty: not other.is_empty
			start_pos_large_enough: start_pos >= 1
			start_pos_small_enough: start_pos <= count
			end_pos_large_enough: end_pos >= start_pos
			end_pos_small_enough: end_pos <= count
		external
			"Python"
		end

	hash_code: INTEGER_32
			-- Hash code value, computed from the characters.
		external
			"Python"
		end

	case_insensitive_hash_code: INTEGER_32
			-- Hash code value of the lower-case version of the string.
		external
			"Python"
		end

	false_constant: STRING_8 = "false"
			-- The text of False.

	true_constant: STRING_8 = "true"
			-- The text of True.

feature -- Measurement

	count: INTEGER_32
			-- Number of characters.
		external
			"Python"
		end

	capacity: INTEGER_32
			-- Number of characters the string can hold without growing.
		external
			"Python"
		end

	occurrences (c: CHARACTER_32): INTEGER_32
			-- Number of times `c' appears in the string.
		external
			"Python"
		end

feature -- Status report

	valid_index (i: INTEGER_32): BOOLEAN
			-- Is `i' a position of the string (1 to `count')?
		do
			Result := i >= 1 and i <= count
		end

	is_empty: BOOLEAN
			-- Is the string empty?
		do
			Result := count = 0
		end

	is_immutable: BOOLEAN
			-- Can the characters of the string never change?
		do
			Result := False
		end

	is_string_8: BOOLEAN
			-- Is the string a sequence of CHARACTER_8?
		deferred
		end

	is_string_32: BOOLEAN
			-- Is the string a sequence of CHARACTER_32?
		deferred
		end

	is_valid_as_string_8: BOOLEAN
			-- Can the string be converted to a STRING_8 without loss?
		deferred
		end

	valid_code (v: NATURAL_32): BOOLEAN
			-- Is `v' a valid character code for the string?
		deferred
		end

	has (c: CHARACTER_32): BOOLEAN
			-- Does the string contain `c'?
		external
			"Python"
		end

	has_substring (other: READABLE_STRING_GENERAL): BOOLEAN
			-- Does the string contain `other'?
		external
			"Python"
		end

	starts_with (s: READABLE_STRING_GENERAL): BOOLEAN
			-- Does the string begin with `s'?
		external
			"Python"
		end

	ends_with (s: READABLE_STRING_GENERAL): BOOLEAN
			-- Does the string end with `s'?
		external
			"Python"
		end

	is_whitespace: BOOLEAN
			-- Is every character white space (True for an empty string)?
		external
			"Python"
		end

	is_boolean: BOOLEAN
			-- Is the string "true" or "false", in any case?
		external
			"Python"
		end

	is_integer, is_integer_32: BOOLEAN
			-- Does the string hold an INTEGER_32 (optional blanks and sign, then digits)?
		external
			"Python"
		end

	is_integer_8: BOOLEAN
			-- Does the string hold an INTEGER_8?
		external
			"Python"
		end

	is_integer_16: BOOLEAN
			-- Does the string hold an INTEGER_16?
		external
			"Python"
		end

	is_integer_64: BOOLEAN
			-- Does the string hold an INTEGER_64?
		external
			"Python"
		end

	is_natural, is_natural_32: BOOLEAN
			-- Does the string hold a NATURAL_32?
		external
			"Python"
		end

	is_natural_8: BOOLEAN
			-- Does the string hold a NATURAL_8?
		external
			"Python"
		end

	is_natural_16: BOOLEAN
			-- Does the string hold a NATURAL_16?
		external
			"Python"
		end

	is_natural_64: BOOLEAN
			-- Does the string hold a NATURAL_64?
		external
			"Python"
		end

	is_real, is_real_32: BOOLEAN
			-- Does the string hold a REAL_32?
		external
			"Python"
		end

	is_double, is_real_64: BOOLEAN
			-- Does the string hold a REAL_64?
		external
			"Python"
		end

	is_number_sequence: BOOLEAN
			-- Does the string hold an integer of any size?
		external
			"Python"
		end

	is_real_sequence: BOOLEAN
			-- Does the string hold a real number of any size?
		external
			"Python"
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Does `other' have the same characters as the string?
		external
			"Python"
		end

	is_less alias "<" (other: like Current): BOOLEAN
			-- Does the string come before `other' in lexicographic order of character codes?
		external
			"Python"
		end

	same_string (other: READABLE_STRING_GENERAL): BOOLEAN
			-- Does `other' have the same characters as the string (whatever its type)?
		external
			"Python"
		end

	is_case_insensitive_equal (other: READABLE_STRING_GENERAL): BOOLEAN
			-- Does `other' have the same characters as the string, ignoring case?
		external
			"Python"
		end

feature -- Conversion

	to_string_8: STRING_8
			-- The characters as a STRING_8.
		require
			is_valid_as_string_8: is_valid_as_string_8
		do
			Result := as_string_8
		end

	as_string_8: STRING_8
			-- The characters as a STRING_8 (the string itself if it is a STRING_8);
			-- characters beyond 255 become the null character.
		external
			"Python"
		end

	as_string_32, to_string_32: STRING_32
			-- The characters as a STRING_32 (the string itself if it is a STRING_32).
		external
			"Python"
		end

	as_lower: like Current
			-- New string with every letter in lower case.
		external
			"Python"
		end

	as_upper: like Current
			-- New string with every letter in upper case.
		external
			"Python"
		end

	to_integer, to_integer_32: INTEGER_32
			-- The INTEGER_32 the string holds.
		require
			is_integer: is_integer_32
		external
			"Python"
		end

	to_integer_8: INTEGER_8
			-- The INTEGER_8 the string holds.
		require
			is_integer_8: is_integer_8
		external
			"Python"
		end

	to_integer_16: INTEGER_16
			-- The INTEGER_16 the string holds.
		require
			is_integer_16: is_integer_16
		external
			"Python"
		end

	to_integer_64: INTEGER_64
			-- The INTEGER_64 the string holds.
		require
			is_integer_64: is_integer_64
		external
			"Python"
		end

	to_natural, to_natural_32: NATURAL_32
			-- The NATURAL_32 the string holds.
		require
			is_natural: is_natural_32
		external
			"Python"
		end

	to_natural_8: NATURAL_8
			-- The NATURAL_8 the string holds.
		require
			is_natural_8: is_natural_8
		external
			"Python"
		end

	to_natural_16: NATURAL_16
			-- The NATURAL_16 the string holds.
		require
			is_natural_16: is_natural_16
		external
			"Python"
		end

	to_natural_64: NATURAL_64
			-- The NATURAL_64 the string holds.
		require
			is_natural_64: is_natural_64
		external
			"Python"
		end

	to_real, to_real_32: REAL_32
			-- The REAL_32 the string holds.
		require
			represents_a_real: is_real
		external
			"Python"
		end

	to_double, to_real_64: REAL_64
			-- The REAL_64 the string holds.
		require
			represents_a_double: is_double
		external
			"Python"
		end

	to_boolean: BOOLEAN
			-- True for "true", False for "false" (in any case).
		require
			is_boolean: is_boolean
		external
			"Python"
		end

	split (a_separator: CHARACTER_32): LIST [like Current]
			-- The parts of the string between occurrences of `a_separator'
			-- (one more part than separators; parts may be empty).
		local
			l_list: ARRAYED_LIST [like Current]
			i, j, n: INTEGER_32
		do
			n := count
			create l_list.make (occurrences (a_separator) + 1)
			from
				i := 1
				j := index_of (a_separator, 1)
			until
				j = 0
			loop
				l_list.extend (substring (i, j - 1))
				i := j + 1
				j := index_of (a_separator, i)
			end
			l_list.extend (substring (i, n))
			Result := l_list
		end

	mirrored: like Current
			-- New string with the characters in reverse order.
		external
			"Python"
		end

feature -- Element change

	plus alias "+" (s: READABLE_STRING_GENERAL): like Current
			-- New string: the characters of the current string followed by those of `s'.
		require
			compatible_strings: is_string_8 implies s.is_valid_as_string_8
		external
			"Python"
		end

feature -- Duplication

	substring (start_index, end_index: INTEGER_32): like Current
			-- New string with the characters at positions `start_index' to `end_index'
			-- (empty if that is not a non-empty range of positions).
		external
			"Python"
		end

	head (n: INTEGER_32): like Current
			-- New string with the first `n' characters (all of them if fewer).
		require
			non_negative_argument: n >= 0
		do
			Result := substring (1, n.min (count))
		end

	tail (n: INTEGER_32): like Current
			-- New string with the last `n' characters (all of them if fewer).
		require
			non_negative_argument: n >= 0
		do
			Result := substring (count - n.min (count) + 1, count)
		end

	copy (other: like Current)
			-- Make the string hold the characters of `other'.
		external
			"Python"
		end

feature -- Output

	out: STRING_8
			-- New STRING_8 with a printable copy of the characters.
		external
			"Python"
		end

end
