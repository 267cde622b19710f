note
	description: "`:=' used for comparison inside a condition."

class
	ASSIGNMENT_IN_CONDITION

create
	make

feature {NONE} -- Initialization

	make
			-- Compare with five.
		local
			x: INTEGER
		do
			x := 5
			if x := 5 then -- E: SYNTAX
				print ("five%N")
			end
		end

end
