note
	description: "Creates tasks in passive regions."

class
	SCHEDULER

create
	make

feature {NONE} -- Initialization

	make
			-- Create three tasks and run them.
		local
			l_first, l_second: separate TASK
			l_third: separate ANY
		do
			create <none> l_first.make (1)
			create <here> l_second.make (2) -- E: SYNTAX
			create <SYSTEM> {separate TASK} l_third.make (3) -- E: SYNTAX
			run (l_first)
			run (l_second)
		end

feature -- Basic operations

	run (a_task: separate TASK)
			-- Run `a_task'.
		do
			a_task.execute
		end

end
