note
	description: "[
		Root class: a pool of workers on their own processors, a shared board created with
		create <NONE> on the root's own processor, and waiting with a wait condition.
		]"

class
	WORKER_POOL_APP

create
	make

feature {NONE} -- Initialization

	make
			-- Run `Pool_size' workers over `Job_count' jobs.
		local
			workers: ARRAYED_LIST [separate WORKER]
			w: separate WORKER
			counter: separate CELL [INTEGER]
			same_board: separate like board
			any_worker: detachable separate ANY
		do
			create board.make (Job_count)
			same_board := board
			create workers.make (Pool_size)
			across 1 |..| Pool_size as i loop
				create w.make (board, 2)
				workers.extend (w)
				start (w)
			end
			any_worker := workers.first
			if attached {separate WORKER} any_worker as first_worker then
				introduce (first_worker, workers.last)
			end
			await (same_board)
			counter := create <NONE> {separate CELL [INTEGER]}.put (0)
			across workers as c loop
				add_done (counter, c.item)
			end
			separate counter as n, board as b do
				print ("jobs done: " + n.item.out + ", results: " + b.result_count.out + "%N")
			end
		end

feature -- Access

	board: separate JOB_BOARD
			-- The shared board.

feature -- Constants

	Pool_size: INTEGER = 3
	Job_count: INTEGER = 12

feature {NONE} -- Implementation

	start (w: separate WORKER)
			-- Let `w' run.
		do
			w.run
		end

	introduce (a, b: separate WORKER)
			-- Make `a' meet `b'.
		do
			a.meet (b)
		end

	await (b: separate JOB_BOARD)
			-- Wait until every job of `b' is complete.
		require
			complete: b.is_complete
		do
		end

	add_done (counter: separate CELL [INTEGER]; w: separate WORKER)
			-- Add the jobs `w' completed to `counter'.
		do
			counter.put (counter.item + w.done)
		end

end
