note
	description: "[
		Conversions between UTF-32 (the code points of a STRING_32) and UTF-8 (the bytes of a
		STRING_8), with EiffelBase's names and behaviour: decoding goes by the leading byte of each
		sequence, as EiffelBase's does, so a string that is not valid UTF-8 gives characters
		rather than an exception (check `is_valid_utf_8_string_8' first when that matters).
	]"

expanded class
	UTF_CONVERTER

feature -- Access

	escape_character: CHARACTER_32 = '%/0xFFFD/'
			-- Unicode replacement character.

feature -- Status report

	is_valid_utf_8_string_8 (s: READABLE_STRING_8): BOOLEAN
			-- Is `s' a sequence of well-formed UTF-8 sequences (a leading byte followed by as many
			-- continuation bytes as it announces)?
		local
			i, n: INTEGER
			c: NATURAL_32
		do
			from
				n := s.count
				Result := True
			until
				i >= n or not Result
			loop
				i := i + 1
				c := s.code (i)
				if c <= 0x7F then
				elseif (c & 0xE0) = 0xC0 and i < n then
					i := i + 1
					Result := is_continuation (s.code (i))
				elseif (c & 0xF0) = 0xE0 and i + 1 < n then
					i := i + 2
					Result := is_continuation (s.code (i - 1)) and is_continuation (s.code (i))
				elseif (c & 0xF8) = 0xF0 and i + 2 < n then
					i := i + 3
					Result := is_continuation (s.code (i - 2)) and is_continuation (s.code (i - 1)) and is_continuation (s.code (i))
				else
					Result := False
				end
			end
		ensure
			class
		end

	utf_8_bytes_count (s: READABLE_STRING_GENERAL; start_pos, end_pos: INTEGER): INTEGER
			-- Number of bytes of the UTF-8 encoding of `s.substring (start_pos, end_pos)'.
		require
			start_position_big_enough: start_pos >= 1
			end_position_big_enough: start_pos <= end_pos + 1
			end_pos_small_enough: end_pos <= s.count
		local
			i: INTEGER
			c: NATURAL_32
		do
			from
				i := start_pos
			until
				i > end_pos
			loop
				c := s.code (i)
				if c <= 0x7F then
					Result := Result + 1
				elseif c <= 0x7FF then
					Result := Result + 2
				elseif c <= 0xFFFF then
					Result := Result + 3
				else
					Result := Result + 4
				end
				i := i + 1
			end
		ensure
			class
		end

feature -- Conversion

	utf_8_string_8_to_string_32 (s: READABLE_STRING_8): STRING_32
			-- The characters whose UTF-8 encoding is `s'.
		do
			create Result.make (s.count)
			utf_8_string_8_into_string_32 (s, Result)
		ensure
			class
		end

	utf_8_string_8_into_string_32 (s: READABLE_STRING_8; a_result: STRING_32)
			-- Append to `a_result' the characters whose UTF-8 encoding is `s'. Each sequence is
			-- read by its leading byte; a sequence cut short by the end of `s' is dropped.
		local
			i, n: INTEGER
			c: NATURAL_32
		do
			from
				n := s.count
			until
				i >= n
			loop
				i := i + 1
				c := s.code (i)
				if c <= 0x7F then
					a_result.append_code (c)
				elseif c <= 0xDF then
					i := i + 1
					if i <= n then
						a_result.append_code (((c & 0x1F) |<< 6) | (s.code (i) & 0x3F))
					end
				elseif c <= 0xEF then
					i := i + 2
					if i <= n then
						a_result.append_code (((c & 0xF) |<< 12) | ((s.code (i - 1) & 0x3F) |<< 6) | (s.code (i) & 0x3F))
					end
				elseif c <= 0xF7 then
					i := i + 3
					if i <= n then
						a_result.append_code (((c & 0x7) |<< 18) | ((s.code (i - 2) & 0x3F) |<< 12) |
							((s.code (i - 1) & 0x3F) |<< 6) | (s.code (i) & 0x3F))
					end
				end
			end
		ensure
			class
		end

	utf_32_string_to_utf_8_string_8 (s: READABLE_STRING_GENERAL): STRING_8
			-- The UTF-8 encoding of the codes of `s', one byte a character.
		do
			create Result.make (s.count)
			utf_32_string_into_utf_8_string_8 (s, Result)
		ensure
			class
		end

	utf_32_string_into_utf_8_string_8 (s: READABLE_STRING_GENERAL; a_result: STRING_8)
			-- Append to `a_result' the UTF-8 encoding of the codes of `s'.
		local
			i, n: INTEGER
			c: NATURAL_32
		do
			from
				n := s.count
			until
				i >= n
			loop
				i := i + 1
				c := s.code (i)
				if c <= 0x7F then
					a_result.append_code (c)
				elseif c <= 0x7FF then
					a_result.append_code ((c |>> 6) | 0xC0)
					a_result.append_code ((c & 0x3F) | 0x80)
				elseif c <= 0xFFFF then
					a_result.append_code ((c |>> 12) | 0xE0)
					a_result.append_code (((c |>> 6) & 0x3F) | 0x80)
					a_result.append_code ((c & 0x3F) | 0x80)
				else
					a_result.append_code ((c |>> 18) | 0xF0)
					a_result.append_code (((c |>> 12) & 0x3F) | 0x80)
					a_result.append_code (((c |>> 6) & 0x3F) | 0x80)
					a_result.append_code ((c & 0x3F) | 0x80)
				end
			end
		ensure
			class
		end

	string_32_to_utf_8_string_8 (s: READABLE_STRING_32): STRING_8
			-- The UTF-8 encoding of `s'.
		do
			Result := utf_32_string_to_utf_8_string_8 (s)
		ensure
			class
		end

	string_32_into_utf_8_string_8 (s: READABLE_STRING_32; a_result: STRING_8)
			-- Append to `a_result' the UTF-8 encoding of `s'.
		do
			utf_32_string_into_utf_8_string_8 (s, a_result)
		ensure
			class
		end

feature {NONE} -- Implementation

	is_continuation (c: NATURAL_32): BOOLEAN
			-- Is `c' a continuation byte (10xxxxxx)?
		do
			Result := (c & 0xC0) = 0x80
		ensure
			class
		end

end
