note
	description: "A typographic quote copied from a document does not open an Eiffel string."

class
	BAD_CHARACTER_UNICODE

create
	make

feature {NONE} -- Initialization

	make
			-- Greet.
		do
			print (“hello”) -- E: SYNTAX-LEXICAL
		end

end
