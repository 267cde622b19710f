class
	JOB_QUEUE

create
	make

feature

	make (n: INTEGER)
		do
			create jobs.make (10)
			workers := n
			across 1 |..| n as i loop
				separate create {separate WORKER}.make (Current) as w do
					w.run
				end
			end
		end

	workers: INTEGER

	has_job: BOOLEAN
		do
			Result := not jobs.is_empty
		end

	job: detachable separate PROCEDURE
		require
			has_job
		do
			Result := jobs.item
		end

	take
		require
			has_job
		do
			jobs.remove
		end

	add (p: separate PROCEDURE)
		do
			jobs.put (p)
		end

	close
			-- One Void per worker: stop.
		do
			across 1 |..| workers as i loop
				jobs.put (Void)
			end
		end

feature {NONE}

	jobs: ARRAYED_QUEUE [detachable separate PROCEDURE]

end
