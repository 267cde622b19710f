note
	description: "`:=' written in a precondition, where an assertion (a boolean expression) belongs."

class
	ASSIGNMENT_IN_PRECONDITION

create
	make

feature {NONE} -- Initialization

	make
		do
			set (1)
		end

feature -- Element change

	value: INTEGER

	set (v: INTEGER)
		require
			v := 0 -- E: SYNTAX
		do
			value := v
		end

end
