note
	description: "The class itself has no closing `end': the parser notices at the end of the file."

class -- E: SYNTAX-END@1
	MISSING_END_CLASS

create
	make

feature {NONE} -- Initialization

	make
			-- Do nothing.
		do
		end

