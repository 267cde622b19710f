note
	description: "Watches for a reading that matches a target value."

class
	READING_WATCH

create
	make

feature {NONE} -- Initialization

	make
			-- Watch for the value "ready".
		do
			target := "ready"
			answer := "ready"
			check_answer
		end

feature -- Access

	answer: detachable separate STRING
			-- Last reading received.

	target: detachable separate STRING
			-- Reading that ends the watch.

	is_done: BOOLEAN
			-- Was the target reading seen?

feature -- Basic operations

	check_answer
			-- Set `is_done' if `answer' is `target'.
		local
			l_answer, l_target: detachable STRING
		do
			if equal (answer, target) then -- E: VUAR(2) VUAR(2)
				is_done := True
			end
			if attached answer as a then
				l_answer := copied (a)
			end
			if attached target as t then
				l_target := copied (t)
			end
			if equal (l_answer, l_target) or answer = target then
				is_done := True
			end
		end

	copied (a_text: separate STRING): STRING
			-- A copy of `a_text' on this processor.
		do
			create Result.make_from_separate (a_text)
		end

end
