note
	description: "A first-in first-out buffer with a fixed capacity."

class
	BOUNDED_BUFFER [G]

create
	make

feature {NONE} -- Initialization

	make (a_capacity: INTEGER)
			-- Create an empty buffer holding at most `a_capacity' items.
		require
			positive_capacity: a_capacity > 0
		do
			capacity := a_capacity
			create items.make (a_capacity)
		ensure
			capacity_set: capacity = a_capacity
			empty: is_empty
		end

feature -- Access

	item: G
			-- The oldest item.
		require
			not_empty: not is_empty
		do
			Result := items.item
		end

	count: INTEGER
			-- Number of items held.
		do
			Result := items.count
		end

	capacity: INTEGER
			-- Largest number of items held at once.

feature -- Status report

	is_empty: BOOLEAN
			-- Is there no item?
		do
			Result := items.is_empty
		end

	is_full: BOOLEAN
			-- Is there no room left?
		do
			Result := count = capacity
		end

feature -- Element change

	put (v: G)
			-- Append `v'.
		require
			not_full: not is_full
		do
			items.extend (v)
		ensure
			one_more: count = old count + 1
		end

	remove
			-- Remove the oldest item.
		require
			not_empty: not is_empty
		do
			items.remove
		ensure
			one_less: count = old count - 1
		end

feature {NONE} -- Implementation

	items: ARRAYED_QUEUE [G]
			-- The items, oldest first.

invariant
	within_capacity: count <= capacity

end
