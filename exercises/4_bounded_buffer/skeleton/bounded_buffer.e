note
	description: "[
		A buffer of at most `capacity' items, first in first out (exercise 4, README.md). It is
		shared: producers and consumers on other processors call it, and wait in their own
		wait conditions until it is not full (to put) or not empty (to take). Given complete.
	]"

class
	BOUNDED_BUFFER [G]

create
	make

feature {NONE} -- Initialization

	make (a_capacity: INTEGER)
			-- An empty buffer for `a_capacity' items.
		require
			positive: a_capacity > 0
		do
			capacity := a_capacity
			create items.make (a_capacity)
		ensure
			empty: is_empty
		end

feature -- Access

	capacity: INTEGER
			-- The most items the buffer holds.

	count: INTEGER
			-- Items in the buffer.
		do
			Result := items.count
		end

	item: G
			-- The oldest item.
		require
			not_empty: not is_empty
		do
			Result := items.item
		end

	largest_count: INTEGER
			-- The most items the buffer has held at once.

feature -- Status report

	is_empty: BOOLEAN
		do
			Result := items.is_empty
		end

	is_full: BOOLEAN
		do
			Result := count = capacity
		end

feature -- Element change

	put (v: G)
			-- Add `v' as the newest item.
		require
			not_full: not is_full
		do
			items.extend (v)
			largest_count := largest_count.max (count)
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
	within_capacity: 0 <= count and count <= capacity
	largest: count <= largest_count and largest_count <= capacity

end
