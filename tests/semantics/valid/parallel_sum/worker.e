note
	description: "A worker that runs the jobs of a job board."

class
	WORKER

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER; a_board: separate JOB_BOARD)
			-- Worker `an_id' taking jobs from `a_board'.
		do
			id := an_id
			board := a_board
		end

feature -- Access

	id: INTEGER
			-- Worker number.

	jobs_done: INTEGER
			-- Jobs run so far.

feature -- Basic operations

	run
			-- Run jobs until the board is closed and has no job left.
		local
			l_done: BOOLEAN
		do
			from
			until
				l_done
			loop
				if attached taken_job (board) as l_job then
					separate l_job as j do
						j.call (Void)
					end
					jobs_done := jobs_done + 1
				else
					l_done := True
				end
			end
			print ("Worker " + id.out + " ran " + jobs_done.out + " jobs%N")
		end

feature {NONE} -- Implementation

	taken_job (a_board: separate JOB_BOARD): detachable separate PROCEDURE [TUPLE]
			-- The next job of `a_board', taken off the board; Void once it is closed and empty.
		require
			job_or_closed: a_board.has_job or a_board.is_closed
		do
			if a_board.has_job then
				Result := a_board.next_job
				a_board.remove_job
			end
		end

	board: separate JOB_BOARD
			-- Where jobs come from.

end
