note
	description: "[
		Condition variables: a thread holding a mutex waits (`wait') until another thread
		signals the variable; the mutex is unlocked while it waits and locked again before
		`wait' returns. Waiters test their condition again in a loop, as with POSIX threads.
	]"
	implementation: "`external %"Python%"' (scoopc/kernel/ext/condition_variable.py)."

class
	CONDITION_VARIABLE

create
	make

feature {NONE} -- Initialization

	make
			-- A condition variable nobody waits on.
		do
			initialize
		ensure
			is_set: is_set
		end

feature -- Access

	is_set: BOOLEAN
			-- Can the condition variable be used (created, not destroyed)?
		external
			"Python"
		end

feature -- Status setting

	signal
			-- Wake one thread waiting on the condition variable, if any.
		require
			is_set: is_set
		do
			host_signal
		end

	broadcast
			-- Wake every thread waiting on the condition variable.
		require
			is_set: is_set
		do
			host_broadcast
		end

	wait (a_mutex: MUTEX)
			-- Unlock `a_mutex', wait for a signal, lock `a_mutex' again.
		require
			is_set: is_set
			a_mutex_not_void: a_mutex /= Void
			is_mutex_set: a_mutex.is_set
			mutex_locked: a_mutex.is_locked_by_current_thread
		do
			host_wait (a_mutex)
		ensure
			mutex_locked: a_mutex.is_locked_by_current_thread
		end

	wait_with_timeout (a_mutex: MUTEX; a_timeout: INTEGER_32): BOOLEAN
			-- As `wait', waiting at most `a_timeout' milliseconds; was it signalled in time?
		require
			is_set: is_set
			a_mutex_not_void: a_mutex /= Void
			is_mutex_set: a_mutex.is_set
			mutex_locked: a_mutex.is_locked_by_current_thread
			timeout_positive: a_timeout >= 0
		do
			Result := host_wait_with_timeout (a_mutex, a_timeout)
		ensure
			mutex_locked: a_mutex.is_locked_by_current_thread
		end

	destroy
			-- Give the condition variable up: it may not be used any more.
		require
			is_set: is_set
		do
			host_destroy
		ensure
			not_set: not is_set
		end

feature {NONE} -- Implementation

	initialize
			-- Make the host's condition variable.
		external
			"Python"
		end

feature {NONE} -- Host

	host_signal
			-- `signal' on the host.
		external
			"Python"
		end

	host_broadcast
			-- `broadcast' on the host.
		external
			"Python"
		end

	host_wait (a_mutex: MUTEX)
			-- `wait' on the host.
		external
			"Python"
		end

	host_wait_with_timeout (a_mutex: MUTEX; a_timeout: INTEGER_32): BOOLEAN
			-- `wait_with_timeout' on the host.
		external
			"Python"
		end

	host_destroy
			-- `destroy' on the host.
		external
			"Python"
		end

end
