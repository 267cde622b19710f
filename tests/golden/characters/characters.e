note
	description: "CHARACTER_8 and CHARACTER_32: codes, arithmetic, classification, escapes."

class
	CHARACTERS

create
	make

feature {NONE} -- Initialization

	make
		local
			c, d: CHARACTER
			w: CHARACTER_32
		do
			c := 'a'
			show ("default code", d.code.out)
			show ("code", c.code.out)
			show ("upper, as_upper", c.upper.out + " " + ('Q').as_lower.out + " " + ('5').upper.out)
			show ("plus, minus", (c + 1).out + " " + ('z' - 1).out)
			show ("difference", ('z' |-| 'a').out)
			show ("is_digit", ('7').is_digit.out + " " + c.is_digit.out)
			show ("is_alpha", c.is_alpha.out + " " + ('_').is_alpha.out)
			show ("is_upper, is_lower", ('A').is_upper.out + " " + ('A').is_lower.out)
			show ("is_space", (' ').is_space.out + " " + ('%T').is_space.out + " " + ('x').is_space.out)
			show ("is_punctuation", ('!').is_punctuation.out + " " + ('a').is_punctuation.out)
			show ("is_hexa_digit", ('f').is_hexa_digit.out + " " + ('g').is_hexa_digit.out)
			show ("comparison", (c < 'b').out + " " + ('B' < 'a').out + " " + (c.max ('m')).out)
			show ("escapes", ('%N').code.out + " " + ('%T').code.out + " " + ('%R').code.out + " " + ('%U').code.out)
			show ("quote, percent", ('%'').out + " " + ('%%').out + " " + ('%"').out)
			show ("by code", ('%/65/').out + ('%/0x42/').out)
			show ("to_character_8", (72).to_character_8.out + (105).to_character_8.out)
			w := 'A'
			show ("CHARACTER_32", w.out + " " + w.code.out + " " + w.natural_32_code.out)
			w := c.to_character_32
			show ("to_character_32", w.out)
			show ("equality", (c = 'a').out + " " + (c /= 'a').out)
			io.put_character (c)
			io.put_character ('%N')
			print (c)
			print ('%N')
		end

	show (label: STRING; value: STRING)
		do
			print (label + ": " + value + "%N")
		end

end
