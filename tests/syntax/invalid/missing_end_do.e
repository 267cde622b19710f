note
	description: "A routine whose `do' part has no `end'."

class
	MISSING_END_DO

create
	make

feature {NONE} -- Initialization

	make
			-- Greet.
		do -- E: SYNTAX-END@3
			print ("hello%N")

feature -- Access

	name: STRING = "missing end"

end
