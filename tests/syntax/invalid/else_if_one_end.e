note
	description: "[
		`else if' written as if it were `elseif': the inner `if' needs its own `end',
		so one `end' is missing and the parser notices at the next feature clause.
		]"

class
	ELSE_IF_ONE_END

create
	make

feature {NONE} -- Initialization

	make
			-- Classify `value'.
		do
			if value < 0 then -- E: SYNTAX-END@4
				print ("negative%N")
			else if value = 0 then
				print ("zero%N")
			else
				print ("positive%N")
			end
		end

feature -- Access

	value: INTEGER = 5

end
