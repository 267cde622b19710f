note
	description: "An opening parenthesis never closed: the parser notices at the next line's first token."

class
	MISSING_CLOSE_PAREN

create
	make

feature {NONE} -- Initialization

	make
			-- Print a sum.
		local
			a, b: INTEGER
		do
			a := 2
			b := 3
			print ((a + b).out + "%N"
			print ("done%N") -- E: SYNTAX
		end

end
