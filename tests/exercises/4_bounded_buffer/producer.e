note
	description: "Exercise 4's reference solution (exercises/4_bounded_buffer): the producer."

class
	PRODUCER

create
	make

feature {NONE} -- Initialization

	make (a_buffer: separate BOUNDED_BUFFER [INTEGER]; a_first, a_total: INTEGER)
			-- A producer of `a_total' numbers from `a_first' on, for `a_buffer'.
		do
			buffer := a_buffer
			first := a_first
			total := a_total
		end

feature -- Access

	buffer: separate BOUNDED_BUFFER [INTEGER]
			-- Where the numbers go.

	first, total: INTEGER
			-- The first number, and how many.

	produced: INTEGER
			-- Numbers put so far.

feature -- Basic operations

	produce
			-- Put the `total' numbers into `buffer', in order.
		do
			from until produced = total loop
				put_next (buffer)
			end
		ensure
			all_put: produced = total
		end

feature {NONE} -- Implementation

	put_next (b: separate BOUNDED_BUFFER [INTEGER])
			-- Put the next number, once `b' has room (the wait condition).
		require
			room: not b.is_full
		do
			b.put (first + produced)
			produced := produced + 1
		end

end
