note
	description: "A counter with no creation clause: objects are made by `default_create'."

class
	TALLY

feature -- Access

	count: INTEGER
			-- How many times `increment' was called.

feature -- Element change

	increment
			-- Add one to `count'.
		do
			count := count + 1
		ensure
			one_more: count = old count + 1
		end

end
