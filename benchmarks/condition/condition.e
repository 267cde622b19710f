note
	description: "[
		SCOOP/Qs condition benchmark: Worker_count workers, half wanting the shared variable
		even and half odd, each wait for their parity and increment it, N times each (so the
		two groups strictly alternate). N is the first argument (default 100000), Worker_count
		the second (default 4, an even number). Prints the final value, which must be
		Worker_count * N.
	]"

class
	CONDITION

inherit
	ARGUMENTS

create
	make

feature {NONE} -- Initialization

	make
			-- Create the variable and the workers, launch them, wait for them, print the value.
		local
			l_shared: separate SHARED
			l_worker: separate WORKER
			l_workers: ARRAYED_LIST [separate WORKER]
			l_iterations, i: INTEGER
		do
			l_iterations := Default_iterations
			if argument_count >= 1 then
				l_iterations := argument (1).to_integer
			end
			worker_count := Default_workers
			if argument_count >= 2 then
				worker_count := argument (2).to_integer
			end
			create l_shared.make
			create l_workers.make (worker_count)
			from
				i := 0
			until
				i = worker_count
			loop
				create l_worker.make (l_shared, i \\ 2, l_iterations)
				l_workers.extend (l_worker)
				launch (l_worker)
				i := i + 1
			end
			across l_workers as w loop
				join (w.item)
			end
			report (l_shared, l_iterations)
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

	report (s: separate SHARED; an_iterations: INTEGER)
			-- Print the value of `s'.
		do
			print ("condition: workers=" + worker_count.out + " iterations=" + an_iterations.out + " value=" + s.value.out + "%N")
		end

	worker_count: INTEGER
			-- Number of workers (an even number: as many want even values as odd ones).

	Default_workers: INTEGER = 4
			-- Number of workers when no second argument is given.

	Default_iterations: INTEGER = 100_000
			-- Increments per worker when no argument is given.

end
