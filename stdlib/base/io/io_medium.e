note
	description: "[
		Anything programs read from or write to: files and the standard streams.
		Reading a value sets the matching `last_...' query.
	]"
	implementation: "[
		The stream lives in the host; features marked `external "Python"' are
		provided by the runtime for every medium, bound by class and feature name.
	]"

deferred class
	IO_MEDIUM

feature -- Access

	name: detachable STRING_8
			-- Name of the medium, if any.
		deferred
		end

	last_character: CHARACTER_8
			-- Last character read.
		external
			"Python"
		end

	last_string: STRING_8
			-- Last string read (a line, a word or a stream).
		external
			"Python"
		end

	last_integer, last_integer_32: INTEGER_32
			-- Last integer read by `read_integer'.
		external
			"Python"
		end

	last_natural, last_natural_32: NATURAL_32
			-- Last natural read by `read_natural'.
		external
			"Python"
		end

	last_real, last_real_32: REAL_32
			-- Last real read by `read_real'.
		external
			"Python"
		end

	last_double, last_real_64: REAL_64
			-- Last real read by `read_double'.
		external
			"Python"
		end

	last_integer_8: INTEGER_8
			-- Last INTEGER_8 read by `read_integer_8'.
		external
			"Python"
		end

	last_integer_16: INTEGER_16
			-- Last INTEGER_16 read by `read_integer_16'.
		external
			"Python"
		end

	last_integer_64: INTEGER_64
			-- Last INTEGER_64 read by `read_integer_64'.
		external
			"Python"
		end

	last_natural_8: NATURAL_8
			-- Last NATURAL_8 read by `read_natural_8'.
		external
			"Python"
		end

	last_natural_16: NATURAL_16
			-- Last NATURAL_16 read by `read_natural_16'.
		external
			"Python"
		end

	last_natural_64: NATURAL_64
			-- Last NATURAL_64 read by `read_natural_64'.
		external
			"Python"
		end

feature -- Status report

	exists: BOOLEAN
			-- Does the medium exist?
		external
			"Python"
		end

	is_open_read: BOOLEAN
			-- Is the medium open for reading?
		external
			"Python"
		end

	is_open_write: BOOLEAN
			-- Is the medium open for writing?
		external
			"Python"
		end

	is_closed: BOOLEAN
			-- Is the medium closed?
		external
			"Python"
		end

	is_readable: BOOLEAN
			-- May the medium be read (by its access rights)?
		external
			"Python"
		end

	is_writable: BOOLEAN
			-- May the medium be written (by its access rights)?
		external
			"Python"
		end

	is_executable: BOOLEAN
			-- May the medium be executed (by its access rights)?
		external
			"Python"
		end

	readable: BOOLEAN
			-- Is there something to read, the medium being open for reading?
		external
			"Python"
		end

	extendible: BOOLEAN
			-- May the medium be written to now (is it open for writing)?
		external
			"Python"
		end

	is_plain_text: BOOLEAN
			-- Is the medium a text medium?
		external
			"Python"
		end

	bytes_read: INTEGER_32
			-- Number of characters read by the last `read_stream'.
		external
			"Python"
		end

feature -- Status setting

	close
			-- Close the medium.
		external
			"Python"
		end

feature -- Output

	put_new_line, new_line
			-- Write a new line.
		require
			extendible: extendible
		external
			"Python"
		end

	put_string (s: READABLE_STRING_8)
			-- Write the characters of `s'.
		require
			extendible: extendible
		external
			"Python"
		end

	put_character (c: CHARACTER_8)
			-- Write `c'.
		require
			extendible: extendible
		external
			"Python"
		end

	put_integer, put_integer_32 (i: INTEGER_32)
			-- Write the decimal representation of `i'.
		require
			extendible: extendible
		external
			"Python"
		end

	put_natural, put_natural_32 (i: NATURAL_32)
			-- Write the decimal representation of `i'.
		require
			extendible: extendible
		external
			"Python"
		end

	put_real, put_real_32 (r: REAL_32)
			-- Write the representation of `r' (as `r.out').
		require
			extendible: extendible
		external
			"Python"
		end

	put_double, put_real_64 (d: REAL_64)
			-- Write the representation of `d' (as `d.out').
		require
			extendible: extendible
		external
			"Python"
		end

	put_boolean (b: BOOLEAN)
			-- Write "True" or "False".
		require
			extendible: extendible
		external
			"Python"
		end

	put_integer_8 (i: INTEGER_8)
			-- Write the decimal representation of `i'.
		require
			extendible: extendible
		external
			"Python"
		end

	put_integer_16 (i: INTEGER_16)
			-- Write the decimal representation of `i'.
		require
			extendible: extendible
		external
			"Python"
		end

	put_integer_64 (i: INTEGER_64)
			-- Write the decimal representation of `i'.
		require
			extendible: extendible
		external
			"Python"
		end

	put_natural_8 (i: NATURAL_8)
			-- Write the decimal representation of `i'.
		require
			extendible: extendible
		external
			"Python"
		end

	put_natural_16 (i: NATURAL_16)
			-- Write the decimal representation of `i'.
		require
			extendible: extendible
		external
			"Python"
		end

	put_natural_64 (i: NATURAL_64)
			-- Write the decimal representation of `i'.
		require
			extendible: extendible
		external
			"Python"
		end

	flush
			-- Write out what is buffered.
		external
			"Python"
		end

feature -- Input

	read_integer, read_integer_32
			-- Read an INTEGER_32 (skipping blanks before it) into `last_integer'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_natural, read_natural_32
			-- Read a NATURAL_32 into `last_natural'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_real, read_real_32
			-- Read a REAL_32 into `last_real'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_double, read_real_64
			-- Read a REAL_64 into `last_double'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_integer_8
			-- Read a INTEGER_8 into `last_integer_8'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_integer_16
			-- Read a INTEGER_16 into `last_integer_16'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_integer_64
			-- Read a INTEGER_64 into `last_integer_64'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_natural_8
			-- Read a NATURAL_8 into `last_natural_8'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_natural_16
			-- Read a NATURAL_16 into `last_natural_16'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_natural_64
			-- Read a NATURAL_64 into `last_natural_64'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_character
			-- Read the next character into `last_character'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_line
			-- Read the characters up to the end of the line into `last_string' (without the new line).
		require
			is_readable: readable
		external
			"Python"
		end

	read_word
			-- Read the next word (characters up to a blank) into `last_string'.
		require
			is_readable: readable
		external
			"Python"
		end

	read_stream (nb_char: INTEGER_32)
			-- Read at most `nb_char' characters into `last_string'.
		require
			is_readable: readable
		external
			"Python"
		end

end
