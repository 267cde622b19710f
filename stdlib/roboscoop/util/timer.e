note
	description: "[
		Time on the runtime's clock (virtual in simulated runs), in seconds: a stopwatch
		(`start', `elapsed', `has_elapsed'), `sleep', and delayed or repeated invocation of
		agents: `call_after' calls an agent once after a delay, `call_every' at a fixed period,
		each as a command logged on the agent's processor (the region where the agent was
		made), so the agent runs like any other call there, never in parallel with it.
		`cancel' drops every pending call of this timer. A pending call keeps the program
		running (a repeated one until cancelled).
	]"

class
	TIMER

create
	make

feature {NONE} -- Initialization

	make
			-- Stopwatch started now, no pending call.
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

	pending_count: INTEGER
			-- Calls scheduled by this timer and still to come (a repeated one counts once).
		external
			"Python"
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

	call_after (a_seconds: REAL_64; a_action: PROCEDURE)
			-- Call `a_action' once, `a_seconds' from now.
		require
			non_negative: a_seconds >= 0.0
		do
			schedule (nanoseconds (a_seconds), 0, a_action)
		ensure
			pending: pending_count = old pending_count + 1
		end

	call_every (a_seconds: REAL_64; a_action: PROCEDURE)
			-- Call `a_action' every `a_seconds' (the first time `a_seconds' from now) until `cancel'.
		require
			positive: a_seconds > 0.0
		do
			schedule (nanoseconds (a_seconds), nanoseconds (a_seconds), a_action)
		ensure
			pending: pending_count = old pending_count + 1
		end

	cancel
			-- Drop every pending call of this timer.
		external
			"Python"
		ensure
			none_pending: pending_count = 0
		end

feature {NONE} -- Implementation

	nanoseconds (a_seconds: REAL_64): INTEGER_64
			-- `a_seconds' in nanoseconds (at least 1).
		do
			Result := (a_seconds * 1.0e9).rounded_real_64.truncated_to_integer_64.max (1)
		end

	schedule (a_delay, a_period: INTEGER_64; a_action: PROCEDURE)
			-- Log `a_action' on its processor after `a_delay' ns, then every `a_period' ns (0: once).
		external
			"Python"
		end

end
