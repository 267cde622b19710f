note
	description: "A C-style new-line character: Eiffel writes %%N, and a character literal holds one character."

class
	BACKSLASH_ESCAPE

create
	make

feature {NONE} -- Initialization

	make
			-- Print a new line.
		do
			print ('\n') -- E: SYNTAX-LEXICAL
		end

end
