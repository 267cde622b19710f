note
	description: "Puts numbered items into a shared buffer, waiting while it is full."

class
	PRODUCER

create
	make

feature {NONE} -- Initialization

	make (a_buffer: separate BOUNDED_BUFFER [INTEGER]; an_id, a_count: INTEGER)
			-- Producer `an_id' that will put `a_count' items into `a_buffer'.
		do
			buffer := a_buffer
			id := an_id
			count := a_count
		end

feature -- Basic operations

	live
			-- Produce every item.
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > count
			loop
				store (buffer, id * 100 + i)
				i := i + 1
			end
		end

feature {NONE} -- Implementation

	store (a_buffer: separate BOUNDED_BUFFER [INTEGER]; v: INTEGER)
			-- Put `v' into `a_buffer' as soon as it has room.
		require
			room: not a_buffer.is_full
		do
			a_buffer.put (v)
			print ("producer " + id.out + " put " + v.out + "%N")
		end

	buffer: separate BOUNDED_BUFFER [INTEGER]
	id: INTEGER
	count: INTEGER

end
