note
	description: "A character literal holding two characters."

class
	BAD_CHARACTER_LITERAL

create
	make

feature {NONE} -- Initialization

	make
			-- Store a separator.
		local
			c: CHARACTER
		do
			c := ', ' -- E: SYNTAX-LEXICAL
			print (c)
		end

end
