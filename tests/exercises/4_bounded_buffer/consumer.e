note
	description: "Exercise 4's reference solution (exercises/4_bounded_buffer): the consumer."

class
	CONSUMER

create
	make

feature {NONE} -- Initialization

	make (a_buffer: separate BOUNDED_BUFFER [INTEGER]; a_total: INTEGER)
			-- A consumer of `a_total' numbers from `a_buffer'.
		do
			buffer := a_buffer
			total := a_total
			create received.make (a_total)
		end

feature -- Access

	buffer: separate BOUNDED_BUFFER [INTEGER]
			-- Where the numbers come from.

	total: INTEGER
			-- How many to take.

	received: ARRAYED_LIST [INTEGER]
			-- The numbers taken, in the order they came.

	sum: INTEGER
			-- Their sum.
		do
			across received as r loop
				Result := Result + r.item
			end
		end

feature -- Status report

	is_done: BOOLEAN
			-- Has it taken all `total' numbers?
		do
			Result := received.count = total
		end

feature -- Basic operations

	consume
			-- Take `total' numbers out of `buffer' (each the oldest there), into `received'.
		do
			from until is_done loop
				take_next (buffer)
			end
		ensure
			done: is_done
		end

feature {NONE} -- Implementation

	take_next (b: separate BOUNDED_BUFFER [INTEGER])
			-- Take the oldest number, once `b' has one (the wait condition).
		require
			something: not b.is_empty
		do
			received.extend (b.item)
			b.remove
		end

end
