note
	description: "Strings of 32-bit characters (CHARACTER_32, Unicode) that can change."
	implementation: "[
		Mutable, indices 1 to `count'. The characters live in the host; features marked
		`external "Python"' are provided by the runtime, bound by class and feature name.
	]"

class
	STRING_32

inherit
	READABLE_STRING_32
		export
			{ANY} make, make_empty, make_filled, make_from_string, make_from_string_general
		end

	STRING_GENERAL
		rename
			append as append_string_general,
			prepend as prepend_string_general,
			same_string as same_string_general,
			starts_with as starts_with_general,
			ends_with as ends_with_general,
			is_case_insensitive_equal as is_case_insensitive_equal_general
		export
			{ANY} make, make_empty
		end

create
	make,
	make_empty,
	make_filled,
	make_from_string,
	make_from_string_general,
	make_from_separate

convert
	as_string_8: {READABLE_STRING_8, STRING_8}

feature -- Access

	item alias "[]" (i: INTEGER_32): CHARACTER_32 assign put
			-- Character at position `i'.
		external
			"Python"
		end

feature -- Element change

	share (other: STRING_32)
			-- Make the string use the characters of `other' themselves: from now on a change
			-- to either string is seen by both.
		external
			"Python"
		ensure
			shared_count: other.count = count
		end

	put (c: CHARACTER_32; i: INTEGER_32)
			-- Replace the character at position `i' by `c'.
		require
			valid_index: valid_index (i)
		external
			"Python"
		end

	append (s: READABLE_STRING_32)
			-- Append the characters of `s'.
		external
			"Python"
		end

	append_string (s: detachable READABLE_STRING_32)
			-- Append the characters of `s', if attached.
		do
			if attached s as l_s then
				append (l_s)
			end
		end

	append_substring (s: READABLE_STRING_32; start_index, end_index: INTEGER_32)
			-- Append the characters of `s' at positions `start_index' to `end_index'.
		require
			start_index_valid: start_index >= 1
			end_index_valid: end_index <= s.count
			valid_bounds: start_index <= end_index + 1
		external
			"Python"
		end

	append_character, extend (c: CHARACTER_32)
			-- Append `c'.
		external
			"Python"
		end

	prepend (s: READABLE_STRING_32)
			-- Prepend the characters of `s'.
		external
			"Python"
		end

	prepend_string (s: detachable READABLE_STRING_32)
			-- Prepend the characters of `s', if attached.
		do
			if attached s as l_s then
				prepend (l_s)
			end
		end

	prepend_character, precede (c: CHARACTER_32)
			-- Prepend `c'.
		external
			"Python"
		end

	prepend_integer (i: INTEGER_32)
			-- Prepend the decimal representation of `i'.
		do
			prepend_string_general (i.out)
		end

	prepend_real (r: REAL_32)
			-- Prepend the representation of `r'.
		do
			prepend_string_general (r.out)
		end

	prepend_double (d: REAL_64)
			-- Prepend the representation of `d'.
		do
			prepend_string_general (d.out)
		end

	prepend_boolean (b: BOOLEAN)
			-- Prepend "True" or "False".
		do
			prepend_string_general (b.out)
		end

	insert_string (s: READABLE_STRING_32; i: INTEGER_32)
			-- Insert the characters of `s' so that the first is at position `i'.
		require
			valid_insertion_index: 1 <= i and i <= count + 1
		external
			"Python"
		end

	insert_character (c: CHARACTER_32; i: INTEGER_32)
			-- Insert `c' at position `i'.
		require
			valid_insertion_index: 1 <= i and i <= count + 1
		external
			"Python"
		end

	replace_substring (s: READABLE_STRING_32; start_index, end_index: INTEGER_32)
			-- Replace the characters at positions `start_index' to `end_index' by those of `s'.
		require
			valid_start_index: 1 <= start_index
			valid_end_index: end_index <= count
			meaningful_interval: start_index <= end_index + 1
		external
			"Python"
		end

	replace_substring_all (original, new: READABLE_STRING_32)
			-- Replace every occurrence of `original' by `new'.
		require
			original_not_empty: not original.is_empty
		external
			"Python"
		end

	set (t: READABLE_STRING_32; n1, n2: INTEGER_32)
			-- Make the string hold the characters of `t' at positions `n1' to `n2' (empty if there are none).
		external
			"Python"
		end

	fill_with (c: CHARACTER_32)
			-- Replace every character by `c'.
		external
			"Python"
		end

	fill_character (c: CHARACTER_32)
			-- Fill the string up to `capacity' with `c'.
		external
			"Python"
		end

	fill_blank
			-- Fill the string up to `capacity' with blanks.
		do
			fill_character (' ')
		end

	replace_blank
			-- Replace every character by a blank.
		do
			fill_with (' ')
		end

	left_justify
			-- Move the characters to the left, blanks after them (same `count').
		external
			"Python"
		end

	right_justify
			-- Move the characters to the right, blanks before them (same `count').
		external
			"Python"
		end

	center_justify
			-- Center the characters between blanks (same `count').
		external
			"Python"
		end

feature -- Removal

	prune (c: CHARACTER_32)
			-- Remove the first occurrence of `c', if any.
		external
			"Python"
		end

	prune_all (c: CHARACTER_32)
			-- Remove every occurrence of `c'.
		external
			"Python"
		end

	prune_all_leading (c: CHARACTER_32)
			-- Remove the occurrences of `c' at the start.
		external
			"Python"
		end

	prune_all_trailing (c: CHARACTER_32)
			-- Remove the occurrences of `c' at the end.
		external
			"Python"
		end

end
