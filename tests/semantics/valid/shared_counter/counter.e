note
	description: "A counter that remembers who incremented it last."

class
	COUNTER

create
	make

feature {NONE} -- Initialization

	make
			-- Counter at zero.
		do
			value := 0
		ensure
			zero: value = 0
		end

feature -- Access

	value: INTEGER
			-- Number of increments so far.

	last_caller: detachable STRING
			-- Name of the client who incremented last, if any.

feature -- Element change

	increment (a_caller: separate STRING)
			-- Add one, on behalf of `a_caller'.
		do
			value := value + 1
			last_caller := create {STRING}.make_from_separate (a_caller)
		ensure
			one_more: value = old value + 1
		end

invariant
	non_negative: value >= 0

end
