note
	description: "Processors that deadlock, break a contract or fail in an asynchronous call."

class
	WORKER

feature -- Access

	other: detachable separate WORKER
			-- The worker this one waits for.

	done: BOOLEAN
			-- Has `go' finished?

feature -- Basic operations

	set_other (a_other: separate WORKER)
			-- Wait for `a_other' in `go'.
		do
			other := a_other
		end

	go
			-- Wait until `other' is done (with the two waiting for each other: a deadlock).
		do
			if attached other as l_other then
				await (l_other)
			end
			done := True
		end

	fail
			-- Fail, with nobody waiting for the outcome (an asynchronous call).
		do
			check never: False end
		end

	needs_positive (n: INTEGER)
			-- Accept a positive `n'.
		require
			positive: n > 0
		do
		end

feature {NONE} -- Implementation

	await (a_other: separate WORKER)
			-- Hold `a_other' and ask it whether it is done.
		do
			(create {EXECUTION_ENVIRONMENT}).sleep (50_000_000)
			if a_other.done then
				done := True
			end
		end

end
