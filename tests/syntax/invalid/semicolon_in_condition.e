note
	description: "A semicolon inside the condition of an `if'."

class
	SEMICOLON_IN_CONDITION

create
	make

feature {NONE} -- Initialization

	make
		local
			x: INTEGER
		do
			x := 4
			if x > 3; then -- E: SYNTAX
				print ("big%N")
			end
		end

end
