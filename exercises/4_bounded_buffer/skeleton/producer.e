note
	description: "[
		Puts `total' numbers into a shared buffer: `first', `first' + 1, ... (exercise 4).
		Complete `produce': each put must wait until the buffer is not full.
	]"

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
			-- TODO
		ensure
			all_put: produced = total
		end

end
