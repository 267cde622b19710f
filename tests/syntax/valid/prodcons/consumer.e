note
	description: "Consumers take numbers out of a separate buffer, waiting while it is empty."

class
	CONSUMER

create
	make

feature {NONE} -- Initialization

	make (a_buffer: separate BOUNDED_BUFFER; a_count: INTEGER)
			-- Consume `a_count' items from `a_buffer'.
		do
			buffer := a_buffer
			count := a_count
		end

feature -- Access

	buffer: separate BOUNDED_BUFFER
	count: INTEGER
	total: INTEGER
			-- Sum of the items consumed.

feature -- Basic operations

	live
			-- Consume every item.
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > count
			loop
				total := total + take (buffer)
				i := i + 1
			end
		end

	take (b: separate BOUNDED_BUFFER): INTEGER
			-- The oldest item of `b', removed; waits while `b' is empty.
		require
			not_empty: not b.is_empty
		do
			Result := b.item
			b.remove
		end

end
