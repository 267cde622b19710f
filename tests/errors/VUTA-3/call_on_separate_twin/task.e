note
	description: "A task a worker robot can carry out."

class
	TASK

create
	make

feature {NONE} -- Initialization

	make
			-- New task, not yet done.
		do
			create label.make_from_string ("fetch")
		end

feature -- Access

	label: STRING
			-- What the task is.

	runs: INTEGER
			-- How many times the task was carried out.

feature -- Basic operations

	carry_out
			-- Do the task once more.
		do
			runs := runs + 1
		end

end
