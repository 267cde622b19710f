note
	description: "[
		Assertions for tests (EiffelStudio's testing library, EQA_ASSERTIONS): `assert' raises a
		developer exception tagged with its message when its condition does not hold, which
		fails the test that called it.
		Deviation: EiffelStudio's class inherits EXCEPTIONS to raise; this one raises a
		DEVELOPER_EXCEPTION itself, so a test class does not get EXCEPTIONS' features.
	]"

class
	EQA_ASSERTIONS

feature -- Basic operations

	frozen assert (a_tag: READABLE_STRING_GENERAL; a_condition: BOOLEAN)
			-- Check `a_condition'; when it does not hold, fail with `a_tag'.
		require
			a_tag_not_void: a_tag /= Void
		local
			failure: DEVELOPER_EXCEPTION
		do
			last_assertion_failed := not a_condition
			if last_assertion_failed then
				on_violation (a_tag)
				create failure
				failure.set_description (a_tag)
				failure.raise
			else
				on_satisfaction (a_tag)
			end
		end

	disassert (a_tag: READABLE_STRING_GENERAL; a_condition: BOOLEAN)
			-- Check that `a_condition' does not hold; when it does, fail with `a_tag'.
		require
			a_tag_not_void: a_tag /= Void
		do
			assert (a_tag, not a_condition)
		end

	on_violation (a_tag: READABLE_STRING_GENERAL)
			-- Called when a check of `assert' failed, before the exception is raised.
		require
			last_assertion_failed: last_assertion_failed
		do
		end

	on_satisfaction (a_tag: READABLE_STRING_GENERAL)
			-- Called when a check of `assert' held.
		require
			last_assertion_succeeded: not last_assertion_failed
		do
		end

feature -- Status report

	last_assertion_failed: BOOLEAN
			-- Did the last check of `assert' fail?

end
