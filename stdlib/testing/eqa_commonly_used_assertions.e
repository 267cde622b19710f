note
	description: "[
		The assertions test routines use most (EiffelStudio's EQA_COMMONLY_USED_ASSERTIONS):
		equality of objects, integers, reals, strings, characters and booleans, attachment,
		arrays. A failure's message is the tag, then what was expected and what came instead.
	]"

class
	EQA_COMMONLY_USED_ASSERTIONS

inherit
	EQA_ASSERTIONS

feature -- Equality

	assert_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: detachable ANY)
			-- Check that `expected ~ actual'.
		require
			a_tag_not_void: a_tag /= Void
		do
			assert (assert_equal_message (a_tag, expected, actual), expected ~ actual)
		end

	assert_not_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: detachable ANY)
			-- Check that `expected /~ actual'.
		require
			a_tag_not_void: a_tag /= Void
		do
			disassert (assert_not_equal_message (a_tag, expected, actual), expected ~ actual)
		end

	assert_reference_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: detachable ANY)
			-- Check that `expected = actual' (the same object).
		require
			a_tag_not_void: a_tag /= Void
		do
			assert (assert_equal_message (a_tag, expected, actual), expected = actual)
		end

	assert_not_reference_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: detachable ANY)
			-- Check that `expected /= actual' (not the same object).
		require
			a_tag_not_void: a_tag /= Void
		do
			disassert (assert_not_equal_message (a_tag, expected, actual), expected = actual)
		end

	assert_integers_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: INTEGER)
			-- Check that `expected = actual'.
		require
			a_tag_not_void: a_tag /= Void
		do
			assert (assert_strings_equal_message (a_tag, expected.out, actual.out), expected = actual)
		end

	assert_integers_not_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: INTEGER)
			-- Check that `expected /= actual'.
		require
			a_tag_not_void: a_tag /= Void
		do
			disassert (assert_strings_not_equal_message (a_tag, expected.out, actual.out), expected = actual)
		end

	assert_reals_equal (a_tag: READABLE_STRING_GENERAL; expected, actual, a_tolerance: REAL_64)
			-- Check that `actual' is within `a_tolerance' of `expected'.
		require
			a_tag_not_void: a_tag /= Void
			tolerance_not_negative: a_tolerance >= 0.0
		local
			text: STRING_32
		do
			create text.make_from_string_general (a_tag)
			text.append_string_general ("%N   within: ")
			text.append_string_general (a_tolerance.out)
			assert (assert_strings_equal_message (text, expected.out, actual.out), (expected - actual).abs <= a_tolerance)
		end

	assert_strings_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: READABLE_STRING_GENERAL)
			-- Check that `expected' and `actual' have the same characters.
		require
			a_tag_not_void: a_tag /= Void
		do
			assert (assert_strings_equal_message (a_tag, expected, actual), expected.same_string (actual))
		end

	assert_strings_not_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: READABLE_STRING_GENERAL)
			-- Check that `expected' and `actual' do not have the same characters.
		require
			a_tag_not_void: a_tag /= Void
		do
			disassert (assert_strings_not_equal_message (a_tag, expected, actual), expected.same_string (actual))
		end

	assert_strings_case_insensitive_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: READABLE_STRING_GENERAL)
			-- Check that `expected' and `actual' are the same string but for case.
		require
			a_tag_not_void: a_tag /= Void
		do
			assert (assert_strings_equal_message (a_tag, expected, actual), expected.is_case_insensitive_equal (actual))
		end

	assert_characters_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: CHARACTER)
			-- Check that `expected = actual'.
		require
			a_tag_not_void: a_tag /= Void
		do
			assert (assert_strings_equal_message (a_tag, expected.out, actual.out), expected = actual)
		end

	assert_characters_not_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: CHARACTER)
			-- Check that `expected /= actual'.
		require
			a_tag_not_void: a_tag /= Void
		do
			disassert (assert_strings_not_equal_message (a_tag, expected.out, actual.out), expected = actual)
		end

	assert_booleans_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: BOOLEAN)
			-- Check that `expected = actual'.
		require
			a_tag_not_void: a_tag /= Void
		do
			assert (assert_strings_equal_message (a_tag, expected.out, actual.out), expected = actual)
		end

	assert_booleans_not_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: BOOLEAN)
			-- Check that `expected /= actual'.
		require
			a_tag_not_void: a_tag /= Void
		do
			disassert (assert_strings_not_equal_message (a_tag, expected.out, actual.out), expected = actual)
		end

	assert_attached (a_tag: READABLE_STRING_GENERAL; object: detachable ANY)
			-- Check that `object' is attached.
		require
			a_tag_not_void: a_tag /= Void
		do
			assert (a_tag, object /= Void)
		end

	assert_void (a_tag: READABLE_STRING_GENERAL; object: detachable ANY)
			-- Check that `object' is Void.
		require
			a_tag_not_void: a_tag /= Void
		do
			assert (a_tag, object = Void)
		end

	assert_predicate (a_tag: READABLE_STRING_GENERAL; pred: PREDICATE)
			-- Check that `pred', which takes no argument, holds.
		require
			a_tag_not_void: a_tag /= Void
			pred_not_void: pred /= Void
		do
			assert (a_tag, pred.item ([]))
		end

feature -- Containers

	assert_arrays_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: ARRAY [detachable ANY])
			-- Check that `expected' and `actual' have equal items (~) in the same order.
		require
			a_tag_not_void: a_tag /= Void
		do
			if attached array_difference (a_tag, expected, actual, False) as l_message then
				assert (l_message, False)
			end
		end

	assert_arrays_reference_equal (a_tag: READABLE_STRING_GENERAL; expected, actual: ARRAY [detachable ANY])
			-- Check that `expected' and `actual' have the same items (=) in the same order.
		require
			a_tag_not_void: a_tag /= Void
		do
			if attached array_difference (a_tag, expected, actual, True) as l_message then
				assert (l_message, False)
			end
		end

feature {NONE} -- Messages

	array_difference (a_tag: READABLE_STRING_GENERAL; expected, actual: ARRAY [detachable ANY]; by_reference: BOOLEAN): detachable STRING_32
			-- The message for the first difference between `expected' and `actual', if any.
		local
			i: INTEGER
			l_tag: STRING_32
		do
			create l_tag.make_from_string_general (a_tag)
			if expected.count /= actual.count then
				l_tag.append_string_general ("-count")
				Result := assert_strings_equal_message (l_tag, expected.count.out, actual.count.out)
			else
				from i := 0 until Result /= Void or i >= expected.count loop
					if (by_reference and expected [expected.lower + i] /= actual [actual.lower + i])
						or (not by_reference and expected [expected.lower + i] /~ actual [actual.lower + i])
					then
						l_tag.append_string_general ("-item #")
						l_tag.append_integer (i + 1)
						Result := assert_equal_message (l_tag, expected [expected.lower + i], actual [actual.lower + i])
					end
					i := i + 1
				end
			end
		end

	void_or_out (an_any: detachable ANY): detachable STRING_32
			-- `an_any' as text (a string as itself), or Void.
		do
			if attached {READABLE_STRING_GENERAL} an_any as l_string then
				create Result.make_from_string_general (l_string)
			elseif attached an_any as l_any then
				create Result.make_from_string_general (l_any.out)
			end
		end

	assert_equal_message (a_tag: READABLE_STRING_GENERAL; expected, actual: detachable ANY): STRING_32
			-- The message saying that `expected' and `actual' should be equal.
		require
			a_tag_not_void: a_tag /= Void
		do
			Result := assert_strings_equal_message (a_tag, void_or_out (expected), void_or_out (actual))
		end

	assert_not_equal_message (a_tag: READABLE_STRING_GENERAL; expected, actual: detachable ANY): STRING_32
			-- The message saying that `expected' and `actual' should differ.
		require
			a_tag_not_void: a_tag /= Void
		do
			Result := assert_strings_not_equal_message (a_tag, void_or_out (expected), void_or_out (actual))
		end

	assert_strings_equal_message (a_tag: READABLE_STRING_GENERAL; expected, actual: detachable READABLE_STRING_GENERAL): STRING_32
			-- The tag, then what was expected and what came.
		require
			a_tag_not_void: a_tag /= Void
		do
			create Result.make_from_string_general (a_tag)
			Result.append_string_general ("%N   expected: ")
			Result.append_string_general (text_or_void (expected))
			Result.append_string_general ("%N   but  got: ")
			Result.append_string_general (text_or_void (actual))
		ensure
			message_not_void: Result /= Void
		end

	assert_strings_not_equal_message (a_tag: READABLE_STRING_GENERAL; expected, actual: detachable READABLE_STRING_GENERAL): STRING_32
			-- The tag, then the value that came and the one it should not have matched.
		require
			a_tag_not_void: a_tag /= Void
		do
			create Result.make_from_string_general (a_tag)
			Result.append_string_general ("%N   got actual value: ")
			Result.append_string_general (text_or_void (actual))
			Result.append_string_general ("%N   should not match: ")
			Result.append_string_general (text_or_void (expected))
		ensure
			message_not_void: Result /= Void
		end

	text_or_void (s: detachable READABLE_STRING_GENERAL): READABLE_STRING_GENERAL
			-- `s', or "Void".
		do
			if attached s as l_s then
				Result := l_s
			else
				Result := "Void"
			end
		end

end
