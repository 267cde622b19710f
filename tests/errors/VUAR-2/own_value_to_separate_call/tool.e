note
	description: "A tool a gripper can hold."

class
	TOOL

create
	make

feature {NONE} -- Initialization

	make (a_name: STRING)
			-- Tool called `a_name'.
		do
			name := a_name
		end

feature -- Access

	name: STRING
			-- Name of the tool.

end
