note
	description: "[
		Control over the execution of threads: yield, sleep, wait for the threads the
		calling thread launched. EiffelThread's THREAD_CONTROL; `current_thread_id'
		is here (EiffelStudio keeps it in THREAD_ENVIRONMENT).
	]"
	implementation: "Python threads: `external %"Python%"' (scoopc/kernel/ext/thread_control.py)."

class
	THREAD_CONTROL

feature -- Access

	current_thread_id: POINTER
			-- Identifier of the calling thread.
		external
			"Python"
		end

feature -- Basic operations

	yield
			-- Let another thread run before the calling one goes on.
		external
			"Python"
		end

	join_all
			-- Wait until every thread launched by the calling thread has terminated.
		external
			"Python"
		end

	sleep (nanoseconds: INTEGER_64)
			-- Suspend the calling thread for `nanoseconds' (10^-9 second).
		require
			non_negative_nanoseconds: nanoseconds >= 0
		do
			host_sleep (nanoseconds)
		end

feature {NONE} -- Host

	host_sleep (nanoseconds: INTEGER_64)
			-- `sleep' on the host.
		external
			"Python"
		end

end
