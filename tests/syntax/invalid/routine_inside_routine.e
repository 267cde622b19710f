note
	description: "A routine declared inside another routine's body (Eiffel has no nested routines)."

class
	ROUTINE_INSIDE_ROUTINE

create
	make

feature {NONE} -- Initialization

	make
		do
			helper (3)
			helper (n: INTEGER) -- E: SYNTAX
				do
					print (n)
				end
		end

end
