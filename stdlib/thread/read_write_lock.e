note
	description: "[
		Read/write locks: any number of threads may hold the read lock at once, one thread
		the write lock, never both. A thread may not take a lock it already holds (that
		would wait for itself): the preconditions say so.
	]"
	implementation: "`external %"Python%"' (scoopc/kernel/ext/read_write_lock.py)."

class
	READ_WRITE_LOCK

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
			-- An unlocked read/write lock.
		do
			initialize
		ensure
			is_set: is_set
		end

	default_create
			-- An unlocked read/write lock (as `make').
		do
			initialize
		ensure then
			is_set: is_set
		end

feature -- Access

	is_set: BOOLEAN
			-- Can the lock be used (created, not destroyed)?
		external
			"Python"
		end

	is_read_locked_by_current_thread: BOOLEAN
			-- Does the calling thread hold the read lock?
		require
			exists: is_set
		do
			Result := host_is_read_locked_by_current_thread
		end

	is_write_locked_by_current_thread: BOOLEAN
			-- Does the calling thread hold the write lock?
		require
			exists: is_set
		do
			Result := host_is_write_locked_by_current_thread
		end

feature -- Status setting

	acquire_read_lock
			-- Take the read lock, waiting while a thread holds the write lock.
		require
			exists: is_set
			not_holding: not is_read_locked_by_current_thread and not is_write_locked_by_current_thread
		do
			host_acquire_read_lock
		ensure
			read_locked: is_read_locked_by_current_thread
		end

	acquire_write_lock
			-- Take the write lock, waiting while any thread holds a lock.
		require
			exists: is_set
			not_holding: not is_read_locked_by_current_thread and not is_write_locked_by_current_thread
		do
			host_acquire_write_lock
		ensure
			write_locked: is_write_locked_by_current_thread
		end

	release_reader_lock
			-- Give the read lock back.
		require
			exists: is_set
			read_locked: is_read_locked_by_current_thread
		do
			host_release_reader_lock
		end

	release_writer_lock
			-- Give the write lock back.
		require
			exists: is_set
			write_locked: is_write_locked_by_current_thread
		do
			host_release_writer_lock
		end

	destroy
			-- Give the lock up: it may not be used any more.
		require
			exists: is_set
		do
			host_destroy
		ensure
			not_set: not is_set
		end

feature {NONE} -- Implementation

	initialize
			-- Make the host's lock.
		external
			"Python"
		end

feature {NONE} -- Host

	host_is_read_locked_by_current_thread: BOOLEAN
			-- `is_read_locked_by_current_thread' on the host.
		external
			"Python"
		end

	host_is_write_locked_by_current_thread: BOOLEAN
			-- `is_write_locked_by_current_thread' on the host.
		external
			"Python"
		end

	host_acquire_read_lock
			-- `acquire_read_lock' on the host.
		external
			"Python"
		end

	host_acquire_write_lock
			-- `acquire_write_lock' on the host.
		external
			"Python"
		end

	host_release_reader_lock
			-- `release_reader_lock' on the host.
		external
			"Python"
		end

	host_release_writer_lock
			-- `release_writer_lock' on the host.
		external
			"Python"
		end

	host_destroy
			-- `destroy' on the host.
		external
			"Python"
		end

end
