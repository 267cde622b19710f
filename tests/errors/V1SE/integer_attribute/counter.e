note
	description: "A counter shared by several clients."

class
	COUNTER

create
	make

feature {NONE} -- Initialization

	make
			-- Counter at zero.
		do
			value := 0
		end

feature -- Access

	value: INTEGER
			-- Current value.

feature -- Element change

	add (n: INTEGER)
			-- Add `n' to `value'.
		do
			value := value + n
		ensure
			added: value = old value + n
		end

end
