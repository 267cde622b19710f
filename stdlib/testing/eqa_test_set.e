note
	description: "[
		A set of related tests (EiffelStudio's AutoTest): every procedure without arguments that
		a descendant exports to all its clients is a test. `scoopc test' runs each test on an
		object of its own, made by `default_create' (which calls `on_prepare'), then calls
		`clean' (which calls `on_clean'), in a runtime of its own: its own processors and once
		values. A test fails when a check of `assert' fails, a contract is violated, an
		exception is not caught, the program deadlocks, an asynchronous call's exception is
		lost, or it runs out of time.
		Deviation: EiffelStudio also gives each test a working directory of its own
		(`file_system', `environment'); scoopc runs every test in the current directory.
	]"

deferred class
	EQA_TEST_SET

inherit
	EQA_COMMONLY_USED_ASSERTIONS
		redefine
			default_create
		end

feature {NONE} -- Initialization

	frozen default_create
			-- Prepare a test: `on_prepare'.
		do
			on_prepare
		ensure then
			prepared: is_prepared
			not_failed: not has_failed
		end

feature -- Access

	asserter: EQA_COMMONLY_USED_ASSERTIONS
			-- The assertions, for tests that check through an object of their own.
		do
			if attached internal_asserter as l_asserter then
				Result := l_asserter
			else
				Result := new_asserter
				internal_asserter := Result
			end
		end

feature -- Status report

	is_prepared: BOOLEAN
			-- Is `Current' ready to run a test?
		do
			Result := True
		end

feature {NONE} -- Status report

	has_failed: BOOLEAN
			-- Did the test that just ran fail (while `on_clean' runs)?

feature -- Status setting

	set_asserter (a: like asserter)
			-- Make `a' the `asserter'.
		do
			internal_asserter := a
		ensure
			asserter_set: asserter = a
		end

feature {NONE} -- Cleaning up

	frozen clean (a_has_failed: BOOLEAN)
			-- Release what `on_prepare' took; `a_has_failed': did the test fail?
		do
			has_failed := a_has_failed
			on_clean
			has_failed := False
		ensure
			not_failed: not has_failed
		end

feature {NONE} -- Events

	on_prepare
			-- Called by `default_create' before each test.
		do
		ensure
			prepared: is_prepared
		end

	on_clean
			-- Called by `clean' after each test, whether it passed or failed.
		do
		end

feature {NONE} -- Implementation

	internal_asserter: detachable like asserter
			-- `asserter' once made.

	new_asserter: EQA_COMMONLY_USED_ASSERTIONS
			-- A new `asserter'.
		do
			create Result
		end

end
