note
	description: "A numbered task."

class
	TASK

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER)
			-- Task number `an_id'.
		do
			id := an_id
		end

feature -- Access

	id: INTEGER
			-- Task number.

	is_done: BOOLEAN
			-- Has the task been executed?

feature -- Basic operations

	execute
			-- Do the task.
		do
			is_done := True
		end

end
