note
	description: "[
		A sum of squares split among workers: the root starts every worker (asynchronous
		commands), then asks each for its part (synchronous queries, which wait by necessity
		until that worker is done) and adds the parts up.
	]"

class
	PARALLEL_SUM

create
	make

feature {NONE} -- Initialization

	make
			-- Start one worker per chunk, collect the partial sums and print the total.
		local
			l_workers: ARRAYED_LIST [separate WORKER]
			l_worker: separate WORKER
			l_total: INTEGER_64
			i: INTEGER
		do
			create l_workers.make (Worker_count)
			from
				i := 1
			until
				i > Worker_count
			loop
				create l_worker.make (i, (i - 1) * Chunk_size + 1, i * Chunk_size)
				start (l_worker)
				l_workers.extend (l_worker)
				i := i + 1
			end
			across l_workers as c loop
				l_total := l_total + part (c.item)
			end
			print ("Sum of the squares of 1.." + Upper_bound.out + ": " + l_total.out + "%N")
			check
				closed_form: l_total = expected_sum (Upper_bound)
			end
		end

feature {NONE} -- Implementation

	start (a_worker: separate WORKER)
			-- Let `a_worker' compute its sum.
		do
			a_worker.compute
		end

	part (a_worker: separate WORKER): INTEGER_64
			-- The sum computed by `a_worker', once it is done.
		do
			Result := a_worker.sum
		end

	expected_sum (n: INTEGER): INTEGER_64
			-- 1 + 4 + 9 + ... + `n' ^ 2, from the closed form.
		require
			non_negative: n >= 0
		local
			l_n: INTEGER_64
		do
			l_n := n
			Result := l_n * (l_n + 1) * (l_n * 2 + 1) // 6
		end

	Worker_count: INTEGER = 4
			-- Number of workers.

	Chunk_size: INTEGER = 2_500
			-- Numbers each worker sums.

	Upper_bound: INTEGER
			-- Last number summed.
		do
			Result := Worker_count * Chunk_size
		end

end
