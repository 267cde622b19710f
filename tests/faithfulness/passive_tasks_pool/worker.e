class
	WORKER

create
	make

feature

	make (q: separate JOB_QUEUE)
		do
			queue := q
		end

	run
		do
			from until not attached next_job (queue) as j loop
				separate j as p do
					p.call ([])
				end
				done := done + 1
			end
			print ("worker done%N")
		end

feature {NONE}

	queue: separate JOB_QUEUE

	done: INTEGER

	next_job (q: separate JOB_QUEUE): detachable separate PROCEDURE
		require
			q.has_job
		do
			Result := q.job
			q.take
		end

end
