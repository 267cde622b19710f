note
	description: "Workers apply a function to jobs taken from a separate board."

class
	WORKER

create
	make

feature {NONE} -- Initialization

	make (a_board: separate JOB_BOARD; an_exponent: INTEGER)
			-- A worker for `a_board' raising each job to `an_exponent'.
		do
			board := a_board
			task := agent power (?, an_exponent)
		end

feature -- Access

	board: separate JOB_BOARD
	task: FUNCTION [INTEGER, INTEGER]
	done: INTEGER
			-- Jobs this worker completed.

	last_partner: detachable separate WORKER
			-- Another worker met on the board, if any.

feature -- Basic operations

	run
			-- Take and complete jobs until none is left.
		local
			job: INTEGER
			finished: BOOLEAN
		do
			from
			until
				finished
			loop
				separate board as b do
					if b.is_exhausted then
						finished := True
					else
						job := b.take
					end
				end
				if not finished then
					deliver (board, job, compute (task, job))
					done := done + 1
				end
			end
		end

	compute (f: FUNCTION [INTEGER, INTEGER]; n: INTEGER): INTEGER
			-- `f' applied to `n'.
		do
			Result := f.item ([n])
		end

	power (n, e: INTEGER): INTEGER
			-- `n' to the power `e'.
		do
			Result := (n ^ e).truncated_to_integer
		end

	deliver (b: separate JOB_BOARD; job, value: INTEGER)
			-- Record the result.
		do
			b.complete (job, value)
		end

	meet (other: separate WORKER)
			-- Remember `other'.
		do
			last_partner := other
		end

end
