note
	description: "A worker that counts how often it was started."

class
	WORKER

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER)
			-- Worker number `an_id'.
		do
			id := an_id
		end

feature -- Access

	id: INTEGER
			-- Worker number.

	runs: INTEGER
			-- Number of times started.

feature -- Basic operations

	run
			-- Do one round of work.
		do
			runs := runs + 1
		end

end
