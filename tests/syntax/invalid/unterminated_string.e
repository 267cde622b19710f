note
	description: "A string literal that is not closed on its line."

class
	UNTERMINATED_STRING

create
	make

feature {NONE} -- Initialization

	make
			-- Greet.
		do
			print ("Hello, world) -- E: SYNTAX-LEXICAL
			print ("%N")
		end

end
