note
	description: "Three tests of COUNTER; `test_twice' expects the wrong value and fails."

class
	COUNTER_TESTS

inherit
	EQA_TEST_SET
		redefine
			on_prepare,
			on_clean
		end

feature {NONE} -- Events

	on_prepare
			-- A fresh counter for each test.
		do
			create counter
			print ("prepared%N")
		end

	on_clean
			-- Say that the test is over, and whether it failed.
		do
			print ("cleaned, failed: " + has_failed.out + "%N")
		end

feature -- Tests

	test_starts_at_zero
			-- A new counter is at zero.
		do
			assert_integers_equal ("zero", 0, counter.value)
		end

	test_twice
			-- Two increments make 2, not 3.
		do
			counter.increment
			counter.increment
			assert_integers_equal ("two", 3, counter.value)
		end

	test_equalities
			-- The other assertions of EQA_TEST_SET.
		do
			counter.increment
			assert ("one", counter.value = 1)
			assert_equal ("equal strings", "ab", "a" + "b")
			assert_strings_equal ("strings", "abc", "ab" + "c")
			assert_reals_equal ("reals", 3.14, 3.141, 0.01)
			assert_booleans_equal ("booleans", True, counter.value > 0)
			assert_attached ("attached", counter)
		end

feature {NONE} -- Not tests

	helper
			-- Not exported: not a test.
		do
			assert ("never run", False)
		end

	counter: COUNTER
			-- The counter under test.
		attribute
			create Result
		end

end
