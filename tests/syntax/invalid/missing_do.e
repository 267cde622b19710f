note
	description: "A routine with locals but no `do': the instructions are read as more declarations."

class
	MISSING_DO

create
	make

feature {NONE} -- Initialization

	make
			-- Print three.
		local
			n: INTEGER
			n := 3 -- E: SYNTAX
			print (n)
		end

end
