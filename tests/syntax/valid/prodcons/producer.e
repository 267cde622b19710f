note
	description: "Producers put numbers into a separate buffer, waiting while it is full."

class
	PRODUCER

create
	make

feature {NONE} -- Initialization

	make (a_buffer: separate BOUNDED_BUFFER; an_id, a_count: INTEGER)
			-- Produce `a_count' items into `a_buffer'.
		do
			buffer := a_buffer
			id := an_id
			count := a_count
		end

feature -- Access

	buffer: separate BOUNDED_BUFFER
			-- Where items go.

	id: INTEGER
			-- Producer number.

	count: INTEGER
			-- How many items to produce.

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
				store (buffer, id * 1000 + i)
				i := i + 1
			end
		end

	store (b: separate BOUNDED_BUFFER; v: INTEGER)
			-- Put `v' into `b' once it has room.
		require
			room: not b.is_full
		do
			b.put (v)
		ensure
			stored: b.count = old b.count + 1
		end

end
