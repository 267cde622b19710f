note
	description: "Jobs waiting for a worker, first come first served."

class
	JOB_BOARD

create
	make

feature {NONE} -- Initialization

	make
			-- Open board with no job.
		do
			create jobs.make (10)
		ensure
			open: not is_closed
			empty: not has_job
		end

feature -- Access

	next_job: separate PROCEDURE [TUPLE]
			-- The job posted first.
		require
			has_job: has_job
		do
			Result := jobs.item
		end

feature -- Status report

	has_job: BOOLEAN
			-- Is a job waiting?
		do
			Result := not jobs.is_empty
		end

	is_closed: BOOLEAN
			-- Will no more jobs be posted?

feature -- Element change

	post (a_job: separate PROCEDURE [TUPLE])
			-- Add `a_job' to the jobs waiting.
		require
			open: not is_closed
		do
			jobs.extend (a_job)
		ensure
			has_job: has_job
		end

	remove_job
			-- Remove the job posted first.
		require
			has_job: has_job
		do
			jobs.remove
		end

	close
			-- Tell the workers no more jobs will come.
		do
			is_closed := True
		ensure
			closed: is_closed
		end

feature {NONE} -- Implementation

	jobs: ARRAYED_QUEUE [separate PROCEDURE [TUPLE]]
			-- Jobs waiting, oldest first.

end
