note
	description: "[
		Mutexes: one thread at a time holds a locked mutex, so threads take turns in
		critical sections. The thread that holds a mutex may lock it again (each `lock'
		then needs its `unlock'); only that thread may unlock it.
	]"
	implementation: "`external %"Python%"' (scoopc/kernel/ext/mutex.py)."

class
	MUTEX

inherit
	ANY
		redefine
			default_create
		end

create
	make,
	default_create

feature {NONE} -- Initialization

	make
			-- Create an unlocked mutex.
		require
			thread_capable: {PLATFORM}.is_thread_capable
		do
			initialize
		ensure
			is_set: is_set
		end

	default_create
			-- Create an unlocked mutex (as `make').
		do
			initialize
		ensure then
			is_set: is_set
		end

feature -- Access

	is_set: BOOLEAN
			-- Can the mutex be used (created, not destroyed)?
		external
			"Python"
		end

	is_locked_by_current_thread: BOOLEAN
			-- Does the calling thread hold the mutex?
		require
			is_set: is_set
		do
			Result := host_is_locked_by_current_thread
		end

feature -- Status setting

	lock
			-- Lock the mutex, waiting until no other thread holds it.
		require
			is_set: is_set
		do
			host_lock
		ensure
			locked: is_locked_by_current_thread
		end

	try_lock: BOOLEAN
			-- Lock the mutex if no other thread holds it; did it?
		require
			is_set: is_set
		do
			Result := host_try_lock
		ensure
			locked_if_true: Result implies is_locked_by_current_thread
		end

	unlock
			-- Unlock the mutex (once for each `lock').
		require
			is_set: is_set
			locked_by_caller: is_locked_by_current_thread
		do
			host_unlock
		end

	destroy
			-- Give the mutex up: it may not be used any more.
		require
			is_set: is_set
		do
			host_destroy
		ensure
			not_set: not is_set
		end

feature {NONE} -- Implementation

	initialize
			-- Make the host's mutex.
		external
			"Python"
		end

feature {NONE} -- Host

	host_is_locked_by_current_thread: BOOLEAN
			-- `is_locked_by_current_thread' on the host.
		external
			"Python"
		end

	host_lock
			-- `lock' on the host.
		external
			"Python"
		end

	host_try_lock: BOOLEAN
			-- `try_lock' on the host.
		external
			"Python"
		end

	host_unlock
			-- `unlock' on the host.
		external
			"Python"
		end

	host_destroy
			-- `destroy' on the host.
		external
			"Python"
		end

end
