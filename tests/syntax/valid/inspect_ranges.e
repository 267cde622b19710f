note
	description: "Multi-branch instructions: inspect/when with values, lists, ranges and constants."

class
	INSPECT_RANGES

create
	make

feature {NONE} -- Initialization

	make
			-- Classify numbers and characters.
		local
			i: INTEGER
			c: CHARACTER
		do
			from
				i := -2
			until
				i > 12
			loop
				print (i.out + ": " + size_of (i) + "%N")
				i := i + 1
			end
			across "Hello, World 42!" as ch loop
				print (kind_of (ch.item))
			end
			print ("%N")
			c := 'q'
			inspect c
			when 'a', 'e', 'i', 'o', 'u' then
				print ("vowel%N")
			when 'b' .. 'd', 'f' .. 'h', 'j' .. 'n', 'p' .. 't', 'v' .. 'z' then
				print ("consonant%N")
			end
			print (colour_name (Green) + "%N")
		end

feature -- Classification

	size_of (n: INTEGER): STRING
			-- A word for the size of `n'.
		do
			inspect n
			when 0 then
				Result := "zero"
			when 1, 2, 3 then
				Result := "few"
			when 4..6 then
				Result := "several"
			when 7 .. 9, 10 then
				Result := "many"
			when -2..-1 then
				Result := "negative"
			else
				Result := "lots"
			end
		end

	kind_of (c: CHARACTER): CHARACTER
			-- 'L' for letters, 'D' for digits, '_' otherwise.
		do
			inspect c
			when 'a'..'z', 'A'..'Z' then
				Result := 'L'
			when '0'..'9' then
				Result := 'D'
			when '%N', '%T', ' ' then
				Result := ' '
			else
				Result := '_'
			end
		end

feature -- Colours

	Red: INTEGER = 1
	Green: INTEGER = 2
	Blue: INTEGER = 3
			-- Colour codes.

	colour_name (code: INTEGER): STRING
			-- Name of colour `code'.
		require
			valid: code >= Red and code <= Blue
		do
			inspect code
			when Red then
				Result := "red"
			when Green then
				Result := "green"
			when Blue then
				Result := "blue"
			end
		end

end
