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
		end

feature -- Basic operations

	live
			-- Consume `count' items.
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > count
			loop
				consume (buffer)
				i := i + 1
			end
		end

feature {NONE} -- Implementation

	consume (a_buffer: separate BOUNDED_BUFFER [INTEGER])
			-- Take the oldest item of `a_buffer' as soon as there is one.
		require
			something_there: not a_buffer.is_empty
		local
			v: INTEGER
		do
			v := a_buffer.item
			a_buffer.remove
			print ("consumer " + id.out + " took " + v.out + "%N")
		end

	buffer: separate BOUNDED_BUFFER [INTEGER]
	id: INTEGER
	count: INTEGER

end
