note
	description: "Integer literals in every notation Eiffel offers, with typed manifest constants."

class
	LITERALS_INTEGER

create
	make

feature {NONE} -- Initialization

	make
			-- Print each literal, so a reader can check the value the compiler gave it.
		local
			small: INTEGER_8
			medium: INTEGER_16
			big: INTEGER_64
			byte: NATURAL_8
			word: NATURAL_32
			n: INTEGER
		do
			n := 42
			show ("decimal", n)
			n := 1_000_000
			show ("underscores", n)
			n := 0xFF
			show ("hex lower", n)
			n := 0XCAFE
			show ("hex upper", n)
			n := 0x7FFF_FFFF
			show ("hex with underscore", n)
			n := 0c777
			show ("octal", n)
			n := 0C17
			show ("octal upper", n)
			n := 0b1010_1010
			show ("binary", n)
			n := 0B11
			show ("binary upper", n)
			n := -17
			show ("negative", n)
			n := - - 3
			show ("double negation", n)
			n := +5
			show ("unary plus", n)
			small := {INTEGER_8} -128
			medium := {INTEGER_16} 32_767
			big := {INTEGER_64} 9_223_372_036_854_775_807
			byte := {NATURAL_8} 255
			word := {NATURAL_32} 0xFFFF_FFFF
			print (small.out + " " + medium.out + " " + big.out + " " + byte.out + " " + word.out + "%N")
			print (({INTEGER_64} 1).out + "%N")
			print ((3).out + "%N")
		end

feature -- Output

	show (label: STRING; value: INTEGER)
			-- Print `value' after `label'.
		do
			print (label)
			print (": ")
			print (value)
			print ("%N")
		end

end
