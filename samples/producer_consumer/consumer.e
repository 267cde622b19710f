note
	description: "Takes items out of a shared buffer, waiting while it is empty."

class
	CONSUMER

create
	make

feature {NONE} -- Initialization

	make (a_buffer: separate BOUNDED_BUFFER [INTEGER]; an_id, a_count: INTEGER)
			-- Consumer `an_id' that will take `a_count' items out of `a_buffer'.
		do
			buffer := a_buffer
			id := an_id
			count := a_count
		ensure
			nothing_taken: taken = 0
		end

feature -- Access

	id: INTEGER
			-- Consumer number.

	count: INTEGER
			-- Items to take.

	taken: INTEGER
			-- Items taken so far.

	total: INTEGER
			-- Sum of the items taken so far.

feature -- Basic operations

	live
			-- Consume `count' items.
		do
			from
			until
				taken = count
			loop
				consume (buffer)
			end
			print ("consumer " + id.out + " took " + taken.out + " items%N")
		end

feature {NONE} -- Implementation

	consume (a_buffer: separate BOUNDED_BUFFER [INTEGER])
			-- Take the oldest item of `a_buffer' as soon as there is one.
		require
			something_there: not a_buffer.is_empty
		do
			total := total + a_buffer.item
			a_buffer.remove
			taken := taken + 1
		ensure
			one_more: taken = old taken + 1
		end

	buffer: separate BOUNDED_BUFFER [INTEGER]
			-- Where the items come from.

invariant
	not_too_many: taken <= count

end
