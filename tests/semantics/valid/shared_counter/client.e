note
	description: "A client that increments the shared counter a number of times."

class
	CLIENT

inherit
	COUNTER_ACCESS

create
	make

feature {NONE} -- Initialization

	make (an_id, a_times: INTEGER)
			-- Client `an_id' who will increment `a_times' times.
		do
			id := an_id
			times := a_times
			name := "client " + an_id.out
		end

feature -- Access

	id: INTEGER
			-- Client number.

	times: INTEGER
			-- Increments to do.

	name: STRING
			-- Name shown by the counter.

feature -- Basic operations

	run
			-- Do every increment, one reservation each.
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > times
			loop
				bump (counter)
				i := i + 1
			end
		end

feature {NONE} -- Implementation

	bump (a_counter: separate COUNTER)
			-- Increment `a_counter' once.
		do
			a_counter.increment (name)
		ensure
			incremented: a_counter.value = old a_counter.value + 1
		end

end
