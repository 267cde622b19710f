note
	description: "`=' used where an assignment was meant: an expression is not an instruction."

class
	EQUALITY_AS_INSTRUCTION

create
	make

feature {NONE} -- Initialization

	make
			-- Set and print `x'.
		local
			x: INTEGER
		do
			x = 5 -- E: SYNTAX
			print (x)
		end

end
