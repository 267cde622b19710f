note
	description: "How many spinners have begun."

class
	COUNTER

feature -- Access

	count: INTEGER
			-- Spinners that have begun.

feature -- Element change

	increment
			-- One more has begun.
		do
			count := count + 1
		end

end
