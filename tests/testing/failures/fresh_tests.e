note
	description: "[
		Each test runs in a runtime of its own: a once value and a processor made by one test
		are not there in the next. Both tests pass only if that holds, in either order.
	]"

class
	FRESH_TESTS

inherit
	EQA_TEST_SET

feature -- Tests

	test_first
		do
			check_fresh
		end

	test_second
		do
			check_fresh
		end

feature {NONE} -- Implementation

	check_fresh
			-- The once counter starts at zero; the worker is new.
		local
			w: separate WORKER
		do
			counter.put (counter.item + 1)
			assert_integers_equal ("the once value is this test's", 1, counter.item)
			create w
			assert ("a new worker", not is_done (w))
			start_alone (w)
		end

	counter: CELL [INTEGER]
			-- Shared by the routines of one region, once per runtime.
		once
			create Result.put (0)
		end

	is_done (w: separate WORKER): BOOLEAN
		do
			Result := w.done
		end

	start_alone (w: separate WORKER)
		do
			w.go
		end

end
