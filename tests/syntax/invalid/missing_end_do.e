note
	description: "A routine whose `do' part has no `end'."

class
	MISSING_END_DO

create
	make

feature {NONE} -- Initialization

	make
			-- Greet.
		do
			print ("hello%N")

feature -- Access -- E: SYNTAX-END

	name: STRING = "missing end"

end
