note
	description: "A robot with a name and a battery level."

class
	ROBOT

create
	make

feature {NONE} -- Initialization

	make (a_name: separate STRING)
			-- Robot called `a_name', fully charged.
		do
			create name.make_from_separate (a_name)
			battery := 100
		end

feature -- Access

	name: STRING
			-- The robot's name.

	battery: INTEGER
			-- Charge in percent.

end
