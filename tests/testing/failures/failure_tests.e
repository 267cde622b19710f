note
	description: "Tests that fail in each way a test can fail but an assertion."

class
	FAILURE_TESTS

inherit
	EQA_TEST_SET

feature -- Tests

	test_deadlock
			-- Two workers each wait, holding themselves, for the other.
		local
			a, b: separate WORKER
		do
			create a
			create b
			link (a, b)
			link (b, a)
			start (a)
			start (b)
			wait_done (a)
		end

	test_contract
			-- A precondition broken by the test.
		local
			w: WORKER
		do
			create w
			w.needs_positive (-1)
		end

	test_lost_exception
			-- An asynchronous call fails and no one looks at its outcome.
		local
			w: separate WORKER
		do
			create w
			fail_on (w)
		end

	test_forever
			-- Computes forever, with no call into the runtime.
		local
			i: INTEGER
		do
			from until i < 0 loop
				i := (i + 1) \\ 1000
			end
		end

	test_waits_forever
			-- Waits for a condition that never holds.
		local
			w: separate WORKER
		do
			create w
			wait_done (w)
		end

feature {NONE} -- Implementation

	link (a_worker, a_other: separate WORKER)
		do
			a_worker.set_other (a_other)
		end

	start (a_worker: separate WORKER)
		do
			a_worker.go
		end

	fail_on (a_worker: separate WORKER)
		do
			a_worker.fail
		end

	wait_done (a_worker: separate WORKER)
		require
			done: a_worker.done
		do
		end

end
