note
	description: "[
		The standard input, output and error streams, as `io' gives them to every object.
		Output goes to `standard_default' (the standard output unless changed); input comes
		from `input'.
	]"
	implementation: "Plain Eiffel over the three CONSOLE files; one output call writes its text whole."

class
	STD_FILES

feature -- Access

	input: PLAIN_TEXT_FILE
			-- Standard input.
		once
			create {CONSOLE} Result.make_open_stdin ("stdin")
		end

	output: PLAIN_TEXT_FILE
			-- Standard output.
		once
			create {CONSOLE} Result.make_open_stdout ("stdout")
		end

	error: PLAIN_TEXT_FILE
			-- Standard error.
		once
			create {CONSOLE} Result.make_open_stderr ("stderr")
		end

	default_output: detachable PLAIN_TEXT_FILE
			-- Where output goes, if set (else to `output').

	standard_default: PLAIN_TEXT_FILE
			-- Where output goes: `default_output' if set, `output' otherwise.
		do
			if attached default_output as l_default then
				Result := l_default
			else
				Result := output
			end
		end

feature -- Status report

	last_character: CHARACTER_8
			-- Last character read.
		do
			Result := input.last_character
		end

	last_string: STRING_8
			-- Last string read (a line, a word or a stream).
		do
			Result := input.last_string
		end

	last_integer, last_integer_32: INTEGER_32
			-- Last integer read by `read_integer'.
		do
			Result := input.last_integer
		end

	last_natural, last_natural_32: NATURAL_32
			-- Last natural read by `read_natural'.
		do
			Result := input.last_natural
		end

	last_real, last_real_32: REAL_32
			-- Last real read by `read_real'.
		do
			Result := input.last_real
		end

	last_double, last_real_64: REAL_64
			-- Last real read by `read_double'.
		do
			Result := input.last_double
		end

	last_integer_8: INTEGER_8
			-- Last INTEGER_8 read by `read_integer_8'.
		do
			Result := input.last_integer_8
		end

	last_integer_16: INTEGER_16
			-- Last INTEGER_16 read by `read_integer_16'.
		do
			Result := input.last_integer_16
		end

	last_integer_64: INTEGER_64
			-- Last INTEGER_64 read by `read_integer_64'.
		do
			Result := input.last_integer_64
		end

	last_natural_8: NATURAL_8
			-- Last NATURAL_8 read by `read_natural_8'.
		do
			Result := input.last_natural_8
		end

	last_natural_16: NATURAL_16
			-- Last NATURAL_16 read by `read_natural_16'.
		do
			Result := input.last_natural_16
		end

	last_natural_64: NATURAL_64
			-- Last NATURAL_64 read by `read_natural_64'.
		do
			Result := input.last_natural_64
		end

feature -- Element change

	set_output_default
			-- Send output to the standard output.
		do
			default_output := output
		end

	set_error_default
			-- Send output to the standard error.
		do
			default_output := error
		end

	set_file_default (f: PLAIN_TEXT_FILE)
			-- Send output to `f'.
		require
			valid_argument: f.is_open_write
		do
			default_output := f
		end

	put_new_line, new_line
			-- Write a new line.
		do
			standard_default.put_new_line
		end

	put_string (s: READABLE_STRING_8)
			-- Write the characters of `s'.
		do
			standard_default.put_string (s)
		end

	put_character (c: CHARACTER_8)
			-- Write `c'.
		do
			standard_default.put_character (c)
		end

	put_integer, put_integer_32 (i: INTEGER_32)
			-- Write the decimal representation of `i'.
		do
			standard_default.put_integer (i)
		end

	put_natural, put_natural_32 (i: NATURAL_32)
			-- Write the decimal representation of `i'.
		do
			standard_default.put_natural (i)
		end

	put_real, put_real_32 (r: REAL_32)
			-- Write the representation of `r' (as `r.out').
		do
			standard_default.put_real (r)
		end

	put_double, put_real_64 (d: REAL_64)
			-- Write the representation of `d' (as `d.out').
		do
			standard_default.put_double (d)
		end

	put_boolean (b: BOOLEAN)
			-- Write "True" or "False".
		do
			standard_default.put_boolean (b)
		end

	put_integer_8 (i: INTEGER_8)
			-- Write the decimal representation of `i'.
		do
			standard_default.put_integer_8 (i)
		end

	put_integer_16 (i: INTEGER_16)
			-- Write the decimal representation of `i'.
		do
			standard_default.put_integer_16 (i)
		end

	put_integer_64 (i: INTEGER_64)
			-- Write the decimal representation of `i'.
		do
			standard_default.put_integer_64 (i)
		end

	put_natural_8 (i: NATURAL_8)
			-- Write the decimal representation of `i'.
		do
			standard_default.put_natural_8 (i)
		end

	put_natural_16 (i: NATURAL_16)
			-- Write the decimal representation of `i'.
		do
			standard_default.put_natural_16 (i)
		end

	put_natural_64 (i: NATURAL_64)
			-- Write the decimal representation of `i'.
		do
			standard_default.put_natural_64 (i)
		end

	flush
			-- Write out what is buffered on `standard_default'.
		do
			standard_default.flush
		end

feature -- Input

	read_integer, read_integer_32
			-- Read an INTEGER_32 (skipping blanks before it) into `last_integer'.
		do
			input.read_integer
		end

	read_natural, read_natural_32
			-- Read a NATURAL_32 into `last_natural'.
		do
			input.read_natural
		end

	read_real, read_real_32
			-- Read a REAL_32 into `last_real'.
		do
			input.read_real
		end

	read_double, read_real_64
			-- Read a REAL_64 into `last_double'.
		do
			input.read_double
		end

	read_integer_8
			-- Read a INTEGER_8 into `last_integer_8'.
		do
			input.read_integer_8
		end

	read_integer_16
			-- Read a INTEGER_16 into `last_integer_16'.
		do
			input.read_integer_16
		end

	read_integer_64
			-- Read a INTEGER_64 into `last_integer_64'.
		do
			input.read_integer_64
		end

	read_natural_8
			-- Read a NATURAL_8 into `last_natural_8'.
		do
			input.read_natural_8
		end

	read_natural_16
			-- Read a NATURAL_16 into `last_natural_16'.
		do
			input.read_natural_16
		end

	read_natural_64
			-- Read a NATURAL_64 into `last_natural_64'.
		do
			input.read_natural_64
		end

	read_character
			-- Read the next character into `last_character'.
		do
			input.read_character
		end

	read_line
			-- Read the characters up to the end of the line into `last_string' (without the new line).
		do
			input.read_line
		end

	read_word
			-- Read the next word (characters up to a blank) into `last_string'.
		do
			input.read_word
		end

	read_stream (nb_char: INTEGER_32)
			-- Read at most `nb_char' characters into `last_string'.
		do
			input.read_stream (nb_char)
		end

	to_next_line, next_line
			-- Skip the rest of the current input line.
		do
			input.next_line
		end

end
