note
	description: "`separate' is a keyword (SCOOP) and cannot name a local variable."

class
	RESERVED_SEPARATE_LOCAL

create
	make

feature {NONE} -- Initialization

	make
			-- Decide whether to run apart.
		local
			separate: BOOLEAN -- E: SYNTAX-RESERVED
		do
			print ("done%N")
		end

end
