note
	description: "A counter shared by every worker of the mutex benchmark."

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
			-- Increments so far.

feature -- Element change

	increment
			-- Add one to `value'.
		do
			value := value + 1
		end

end
