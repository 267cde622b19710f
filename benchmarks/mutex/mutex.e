note
	description: "[
		SCOOP/Qs mutex benchmark: Worker_count workers each reserve a shared counter N times
		and increment it. N is the first argument (default 100000), Worker_count the second
		(default 32). Prints the final count, which must be Worker_count * N.
	]"

class
	MUTEX

inherit
	ARGUMENTS

create
	make

feature {NONE} -- Initialization

	make
			-- Create the counter and the workers, launch them, wait for them, print the count.
		local
			l_counter: separate COUNTER
			l_worker: separate WORKER
			l_workers: ARRAYED_LIST [separate WORKER]
			l_iterations: INTEGER
		do
			l_iterations := Default_iterations
			if argument_count >= 1 then
				l_iterations := argument (1).to_integer
			end
			worker_count := Default_workers
			if argument_count >= 2 then
				worker_count := argument (2).to_integer
			end
			create l_counter.make
			create l_workers.make (worker_count)
			across 1 |..| worker_count as i loop
				create l_worker.make (l_counter, l_iterations)
				l_workers.extend (l_worker)
				launch (l_worker)
			end
			across l_workers as w loop
				join (w.item)
			end
			report (l_counter, l_iterations)
		end

feature {NONE} -- Implementation

	launch (w: separate WORKER)
			-- Let `w' make its increments.
		do
			w.live
		end

	join (w: separate WORKER)
			-- Wait until `w' has made its increments.
		require
			done: w.is_done
		do
		end

	report (c: separate COUNTER; an_iterations: INTEGER)
			-- Print the count of `c'.
		do
			print ("mutex: workers=" + worker_count.out + " iterations=" + an_iterations.out + " count=" + c.value.out + "%N")
		end

	worker_count: INTEGER
			-- Number of workers.

	Default_workers: INTEGER = 32
			-- Number of workers when no second argument is given.

	Default_iterations: INTEGER = 100_000
			-- Increments per worker when no argument is given.

end
