note
	description: "A processor that spins for ever without a runtime call, once it has told its counter."

class
	SPINNER

create
	make

feature {NONE} -- Initialization

	make (a_counter: separate COUNTER)
			-- Tell `a_counter' when spinning begins.
		do
			counter := a_counter
		end

feature -- Basic operations

	spin
			-- Tell the counter, then spin for ever.
		local
			n: INTEGER_64
		do
			tell (counter)
			from until n < 0 loop
				n := n + 1
			end
		end

feature {NONE} -- Implementation

	counter: separate COUNTER
			-- Told when spinning begins.

	tell (a_counter: separate COUNTER)
			-- One more spinner has begun.
		do
			a_counter.increment
		end

end
