note
	description: "A thread that calls an agent."

class
	WORKER_THREAD

inherit
	THREAD
		rename
			make as thread_make
		end

create
	make

feature {NONE} -- Initialization

	make (a_action: PROCEDURE [TUPLE])
			-- A thread that will call `a_action'.
		do
			thread_make
			thread_procedure := a_action
		ensure
			action_set: thread_procedure = a_action
		end

feature {NONE} -- Implementation

	thread_procedure: PROCEDURE [TUPLE]
			-- What `execute' calls.

	execute
			-- Call `thread_procedure'.
		do
			thread_procedure.call (Void)
		end

end
