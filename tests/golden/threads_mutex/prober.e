note
	description: "A thread trying a mutex without waiting, then waiting on a semaphore."

class
	PROBER

inherit
	THREAD
		rename
			make as thread_make
		end

create
	make

feature {NONE} -- Initialization

	make (a_mutex: MUTEX; a_gate: SEMAPHORE)
		do
			thread_make
			steps := "steps:"
			mutex := a_mutex
			gate := a_gate
		end

feature -- Access

	mutex: MUTEX
	gate: SEMAPHORE
	got_lock: BOOLEAN
	passed_gate: BOOLEAN
	steps: STRING
			-- What `execute' did (a constant string would be one object per thread).

feature -- Basic operations

	execute
		do
			got_lock := mutex.try_lock
			if got_lock then
				mutex.unlock
			end
			gate.wait
			passed_gate := True
			steps.append (" gate")
			exit
			steps.append (" after exit")
		end

end
