note
	description: "Integer literals that fit no integer type: beyond NATURAL_64 or below INTEGER_64, in every base."

class
	INTEGER_OUT_OF_RANGE

create
	make

feature {NONE} -- Initialization

	Big: INTEGER_32 = 99999999999999999999 -- E: SYNTAX-LEXICAL@20

	make
			-- Print numbers no type holds.
		local
			x: INTEGER
			y: INTEGER_64
		do
			x := 99999999999999999999 -- E: SYNTAX-LEXICAL@9
			y := -9223372036854775809 -- E: SYNTAX-LEXICAL@9
			print (18446744073709551616) -- E: SYNTAX-LEXICAL@11
			print (0x1_0000_0000_0000_0000) -- E: SYNTAX-LEXICAL@11
			print (0c2000000000000000000000) -- E: SYNTAX-LEXICAL@11
			print (0b1_0000000000000000000000000000000000000000000000000000000000000000) -- E: SYNTAX-LEXICAL@11
			print (x + y)
		end

end
