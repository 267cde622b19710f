note
	description: "The variable shared by the workers of the condition benchmark."

class
	SHARED

create
	make

feature {NONE} -- Initialization

	make
			-- Variable at zero.
		do
			value := 0
		ensure
			zero: value = 0
		end

feature -- Access

	value: INTEGER
			-- Increments so far.

feature -- Element change

	increment
			-- Add one to `value'.
		do
			value := value + 1
		end

end
