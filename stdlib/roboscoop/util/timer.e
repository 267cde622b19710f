note
	description: "Time on the runtime's clock (virtual in simulated runs), in seconds; a stopwatch."

class
	TIMER

create
	make

feature {NONE} -- Initialization

	make
			-- Stopwatch started now.
		do
			start
		end

feature -- Access

	now: REAL_64
			-- Seconds on the runtime's clock.
		external
			"Python"
		end

	started_at: REAL_64
			-- Clock reading at the last `start'.

	elapsed: REAL_64
			-- Seconds since the last `start'.
		do
			Result := now - started_at
		end

feature -- Status report

	has_elapsed (a_seconds: REAL_64): BOOLEAN
			-- Have `a_seconds' passed since the last `start'?
		do
			Result := elapsed >= a_seconds
		end

feature -- Basic operations

	start
			-- Restart the stopwatch.
		do
			started_at := now
		end

	sleep (a_seconds: REAL_64)
			-- Suspend the current processor for `a_seconds' on the runtime's clock.
		require
			non_negative: a_seconds >= 0.0
		do
			(create {EXECUTION_ENVIRONMENT}).sleep ((a_seconds * 1.0e9).truncated_to_integer_64)
		end

end
