note
	description: "A thread adding to a shared counter under a mutex, counting its own turns in a once per thread."

class
	ADDER

inherit
	THREAD
		rename
			make as thread_make
		end

create
	make

feature {NONE} -- Initialization

	make (a_counter: SHARED_COUNTER; a_mutex: MUTEX; a_times: INTEGER)
		do
			thread_make
			counter := a_counter
			mutex := a_mutex
			times := a_times
		end

feature -- Access

	counter: SHARED_COUNTER
	mutex: MUTEX
	times: INTEGER

	turns_seen: INTEGER
			-- The value of this thread's own `turns' when `execute' ended.

	turns: CELL [INTEGER]
			-- One cell per thread: a once is per thread in a thread system.
		once
			create Result.put (0)
		end

feature -- Basic operations

	execute
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > times
			loop
				mutex.lock
				counter.increment
				mutex.unlock
				turns.put (turns.item + 1)
				i := i + 1
			end
			turns_seen := turns.item
		end

end
