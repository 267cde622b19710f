note
	description: "C-style `==' for equality."

class
	DOUBLE_EQUALS

create
	make

feature {NONE} -- Initialization

	make
			-- Compare two numbers.
		local
			a, b: INTEGER
		do
			a := 1
			b := 1
			if a == b then -- E: SYNTAX
				print ("equal%N")
			end
		end

end
