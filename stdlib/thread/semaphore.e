note
	description: "[
		Counting semaphores: `wait' takes one unit of the count, waiting while it is 0;
		`post' gives one back. A semaphore made with count n lets n threads into a
		critical section at once.
	]"
	implementation: "`external %"Python%"' (scoopc/kernel/ext/semaphore.py)."

class
	SEMAPHORE

create
	make

feature {NONE} -- Initialization

	make (a_count: INTEGER_32)
			-- A semaphore whose count is `a_count'.
		require
			count_positive: a_count >= 0
		do
			initialize (a_count)
		ensure
			is_set: is_set
		end

feature -- Access

	is_set: BOOLEAN
			-- Can the semaphore be used (created, not destroyed)?
		external
			"Python"
		end

feature -- Status setting

	wait
			-- Decrement the count, waiting until it is positive.
		require
			valid_semaphore: is_set
		do
			host_wait
		end

	try_wait: BOOLEAN
			-- Decrement the count if it is positive, without waiting; did it?
		require
			valid_semaphore: is_set
		do
			Result := host_try_wait
		end

	post
			-- Increment the count (a thread waiting in `wait' may go on).
		require
			valid_semaphore: is_set
		do
			host_post
		end

	destroy
			-- Give the semaphore up: it may not be used any more.
		require
			valid_semaphore: is_set
		do
			host_destroy
		ensure
			not_set: not is_set
		end

feature {NONE} -- Implementation

	initialize (a_count: INTEGER_32)
			-- Make the host's semaphore with count `a_count'.
		external
			"Python"
		end

feature {NONE} -- Host

	host_wait
			-- `wait' on the host.
		external
			"Python"
		end

	host_try_wait: BOOLEAN
			-- `try_wait' on the host.
		external
			"Python"
		end

	host_post
			-- `post' on the host.
		external
			"Python"
		end

	host_destroy
			-- `destroy' on the host.
		external
			"Python"
		end

end
