note
	description: "A mutex benchmark worker: reserves the shared counter `iterations' times and increments it."

class
	WORKER

create
	make

feature {NONE} -- Initialization

	make (a_counter: separate COUNTER; an_iterations: INTEGER)
			-- Worker that will increment `a_counter' `an_iterations' times.
		do
			counter := a_counter
			iterations := an_iterations
		end

feature -- Access

	iterations: INTEGER
			-- Increments to make.

	is_done: BOOLEAN
			-- Has every increment been made?

feature -- Basic operations

	live
			-- Increment the counter `iterations' times, each in its own reservation.
		do
			across 1 |..| iterations as i loop
				increment (counter)
			end
			is_done := True
		end

feature {NONE} -- Implementation

	increment (c: separate COUNTER)
			-- Increment `c' under its reservation.
		do
			c.increment
		end

	counter: separate COUNTER
			-- The shared counter.

end
