note
	description: "[
		Threads of a thread system: a descendant effects `execute', and `launch' runs it
		in a new thread. `join', `join_with_timeout' and `join_all' wait for threads to
		terminate. An exception that escapes `execute' ends the program, as in EiffelStudio.
	]"
	implementation: "Python threads: `external %"Python%"' (scoopc/kernel/ext/thread.py, scoopc/kernel/threads.py)."

deferred class
	THREAD

inherit
	THREAD_CONTROL

feature {NONE} -- Initialization

	make
			-- Initialize Current (not launched, not terminated).
		do
			reset_launch_state
		ensure
			launchable: is_launchable
		end

feature -- Access

	thread_id: POINTER
			-- Identifier of the thread running `execute' (the default pointer when none runs).
		external
			"Python"
		end

	terminated: BOOLEAN
			-- Has the thread launched by Current terminated?
		external
			"Python"
		end

feature -- Basic operations

	execute
			-- What the new thread does.
		deferred
		end

	frozen launch
			-- Start a new thread running `execute'; `is_last_launch_successful' tells whether
			-- this call started it.
		require
			thread_capable: {PLATFORM}.is_thread_capable
			is_launchable: is_launchable
		do
			launch_with_attributes (create {THREAD_ATTRIBUTES}.make)
		end

	frozen launch_with_attributes (attr: THREAD_ATTRIBUTES)
			-- Start a new thread running `execute', with attributes `attr'.
		require
			thread_capable: {PLATFORM}.is_thread_capable
			is_launchable: is_launchable
		do
			start_thread
		end

	exit
			-- End the calling thread, which must be Current's.
		require
			is_exit_supported: is_exit_supported
			self: current_thread_id = thread_id
		do
			host_exit
		end

feature -- Status report

	is_exit_supported: BOOLEAN = True
			-- Can `exit' be called?

	is_launchable: BOOLEAN
			-- Can a new thread be launched with Current (never launched yet)?
		external
			"Python"
		end

	is_last_launch_successful: BOOLEAN
			-- Did the calling thread's last `launch' or `launch_with_attributes' start a thread?
		external
			"Python"
		end

feature -- Synchronization

	join
			-- Wait until the thread launched by Current has terminated.
		external
			"Python"
		end

	join_with_timeout (a_timeout_ms: NATURAL_64): BOOLEAN
			-- Wait at most `a_timeout_ms' milliseconds for the thread launched by Current to
			-- terminate; did it terminate?
		external
			"Python"
		end

feature {NONE} -- Implementation

	frozen thr_main
			-- What the new thread runs.
		do
			execute
		end

	start_thread
			-- Start a Python thread calling `thr_main'.
		external
			"Python"
		end

	reset_launch_state
			-- Forget any earlier launch of Current.
		external
			"Python"
		end

feature {NONE} -- Host

	host_exit
			-- `exit' on the host.
		external
			"Python"
		end

end
