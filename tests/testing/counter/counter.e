note
	description: "A counter, the class under test."

class
	COUNTER

feature -- Access

	value: INTEGER
			-- How many times `increment' was called.

feature -- Element change

	increment
			-- Count one more.
		do
			value := value + 1
		ensure
			one_more: value = old value + 1
		end

end
