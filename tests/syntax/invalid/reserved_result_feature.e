note
	description: "`Result' is reserved: a feature cannot be called `result'."

class
	RESERVED_RESULT_FEATURE

create
	make

feature {NONE} -- Initialization

	make
		do
			print ("done%N")
		end

feature -- Access

	result: INTEGER -- E: SYNTAX-RESERVED
			-- The outcome.

end
