note
	description: "[
		A sum of squares computed by a pool of workers: each chunk of the range is a task
		living in a passive region that posts an agent on a job board; the workers take the
		agents off the board and run them, and every task adds its partial sum to an accumulator.
	]"

class
	PARALLEL_SUM

create
	make

feature {NONE} -- Initialization

	make
			-- Start the workers, post one task per chunk and print the total.
		local
			l_board: separate JOB_BOARD
			l_total: separate ACCUMULATOR
			l_worker: separate WORKER
			l_task: separate CHUNK_TASK
			i: INTEGER
		do
			create l_board.make
			create l_total.make
			across 1 |..| Worker_count as w loop
				create l_worker.make (w.item, l_board)
				start (l_worker)
			end
			from
				i := 0
			until
				i = Chunk_count
			loop
				create <NONE> l_task.make (l_board, l_total, i * Chunk_size + 1, (i + 1) * Chunk_size)
				i := i + 1
			end
			separate l_board as b do
				b.close
			end
			report (l_total)
		end

feature {NONE} -- Implementation

	start (a_worker: separate WORKER)
			-- Let `a_worker' run jobs until the board is closed and empty.
		do
			a_worker.run
		end

	report (a_total: separate ACCUMULATOR)
			-- Print the sum once every chunk has been added.
		require
			every_chunk_added: a_total.contributions = Chunk_count
		do
			print ("Sum of the squares of 1.." + (Chunk_count * Chunk_size).out + ": " + a_total.sum.out + "%N")
		end

	Worker_count: INTEGER = 4
			-- Number of workers.

	Chunk_count: INTEGER = 8
			-- Number of tasks.

	Chunk_size: INTEGER = 50
			-- Numbers summed by each task.

end
