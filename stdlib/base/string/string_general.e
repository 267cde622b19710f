note
	description: "[
		Strings whose characters can change: the modifications common to STRING_8
		and STRING_32 (appending numbers, adjusting, cutting, case changes).
	]"
	implementation: "Externals are provided by the runtime, bound by class and feature name."

deferred class
	STRING_GENERAL

inherit
	READABLE_STRING_GENERAL

feature -- Element change
	append (s: READABLE_STRING_GENERAL)
			-- Append the characters of `s'.
		require
			compatible_strings: is_string_8 implies s.is_valid_as_string_8
		external
			"Python"
		end

	prepend (s: READABLE_STRING_GENERAL)
			-- Prepend the characters of `s'.
		require
			compatible_strings: is_string_8 implies s.is_valid_as_string_8
		external
			"Python"
		end

	append_code (c: NATURAL_32)
			-- Append the character of code `c'.
		require
			valid_code: valid_code (c)
		external
			"Python"
		end

	put_code (v: NATURAL_32; i: INTEGER_32)
			-- Replace the character at position `i' by the character of code `v'.
		require
			valid_code: valid_code (v)
			valid_index: valid_index (i)
		external
			"Python"
		end

	append_integer (i: INTEGER_32)
			-- Append the decimal representation of `i'.
		external
			"Python"
		end

	append_integer_8 (i: INTEGER_8)
			-- Append the decimal representation of `i'.
		external
			"Python"
		end

	append_integer_16 (i: INTEGER_16)
			-- Append the decimal representation of `i'.
		external
			"Python"
		end

	append_integer_64 (i: INTEGER_64)
			-- Append the decimal representation of `i'.
		external
			"Python"
		end

	append_natural_8 (i: NATURAL_8)
			-- Append the decimal representation of `i'.
		external
			"Python"
		end

	append_natural_16 (i: NATURAL_16)
			-- Append the decimal representation of `i'.
		external
			"Python"
		end

	append_natural_32 (i: NATURAL_32)
			-- Append the decimal representation of `i'.
		external
			"Python"
		end

	append_natural_64 (i: NATURAL_64)
			-- Append the decimal representation of `i'.
		external
			"Python"
		end

	append_real (r: REAL_32)
			-- Append the representation of `r' (as `r.out').
		external
			"Python"
		end

	append_double (d: REAL_64)
			-- Append the representation of `d' (as `d.out').
		external
			"Python"
		end

	append_boolean (b: BOOLEAN)
			-- Append "True" or "False".
		external
			"Python"
		end

	keep_head (n: INTEGER_32)
			-- Keep only the first `n' characters (all of them if fewer).
		require
			non_negative_argument: n >= 0
		external
			"Python"
		end

	keep_tail (n: INTEGER_32)
			-- Keep only the last `n' characters (all of them if fewer).
		require
			non_negative_argument: n >= 0
		external
			"Python"
		end

	left_adjust
			-- Remove the leading white space.
		external
			"Python"
		end

	right_adjust
			-- Remove the trailing white space.
		external
			"Python"
		end

	adjust
			-- Remove the leading and trailing white space.
		do
			left_adjust
			right_adjust
		end

	to_lower
			-- Convert every letter to lower case.
		external
			"Python"
		end

	to_upper
			-- Convert every letter to upper case.
		external
			"Python"
		end

	mirror
			-- Reverse the order of the characters.
		external
			"Python"
		end

	multiply (n: INTEGER_32)
			-- Repeat the characters so that they appear `n' times.
		require
			meaningful_multiplier: n >= 1
		external
			"Python"
		end

	set_count (number: INTEGER_32)
			-- Make the string `number' characters long (new characters are null).
		require
			valid_count: 0 <= number and number <= capacity
		external
			"Python"
		end

feature -- Removal

	remove (i: INTEGER_32)
			-- Remove the character at position `i'.
		require
			valid_index: valid_index (i)
		external
			"Python"
		end

	remove_head (n: INTEGER_32)
			-- Remove the first `n' characters (all of them if fewer).
		require
			n_non_negative: n >= 0
		external
			"Python"
		end

	remove_tail (n: INTEGER_32)
			-- Remove the last `n' characters (all of them if fewer).
		require
			n_non_negative: n >= 0
		external
			"Python"
		end

	remove_substring (start_index, end_index: INTEGER_32)
			-- Remove the characters at positions `start_index' to `end_index'.
		require
			valid_start_index: 1 <= start_index
			valid_end_index: end_index <= count
			meaningful_interval: start_index <= end_index + 1
		external
			"Python"
		end

	wipe_out
			-- Remove every character.
		external
			"Python"
		end

feature -- Resizing

	resize (newsize: INTEGER_32)
			-- Make room for at least `newsize' characters.
		require
			new_size_large_enough: newsize >= count
		external
			"Python"
		end

	grow (newsize: INTEGER_32)
			-- Make room for at least `newsize' characters.
		external
			"Python"
		end

	trim
			-- Make `capacity' equal to `count'.
		external
			"Python"
		end

end
