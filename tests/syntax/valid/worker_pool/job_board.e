note
	description: "A board of numbered jobs that workers on other processors take and complete."

class
	JOB_BOARD

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER)
			-- A board with jobs 1 to `n'.
		do
			next_job := 1
			last_job := n
			create results.make (n)
		end

feature -- Access

	next_job, last_job: INTEGER
	results: HASH_TABLE [INTEGER, INTEGER]
			-- Result of each finished job, by job number.

	is_exhausted: BOOLEAN
			-- Have all jobs been handed out?
		do
			Result := next_job > last_job
		end

	result_count: INTEGER
			-- Number of completed jobs.
		do
			Result := results.count
		end

	is_complete: BOOLEAN
			-- Have all jobs been completed?
		do
			Result := results.count = last_job
		end

feature -- Element change

	take: INTEGER
			-- Hand out the next job.
		require
			jobs_left: not is_exhausted
		do
			Result := next_job
			next_job := next_job + 1
		end

	complete (job, value: INTEGER)
			-- Record `value' for `job'.
		do
			results.force (value, job)
		end

end
