note
	description: "A bounded queue of integers, shared by producers and consumers on other processors."

class
	BOUNDED_BUFFER

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER)
			-- Create a buffer for `n' items.
		require
			n_positive: n > 0
		do
			create items.make (n)
			capacity := n
		end

feature -- Access

	capacity: INTEGER
			-- Largest number of items.

	count: INTEGER
			-- Number of items.
		do
			Result := items.count
		end

	item: INTEGER
			-- The oldest item.
		require
			not_empty: not is_empty
		do
			Result := items.item
		end

feature -- Status report

	is_empty: BOOLEAN
		do
			Result := items.is_empty
		end

	is_full: BOOLEAN
		do
			Result := items.count >= capacity
		end

feature -- Element change

	put (v: INTEGER)
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
		end

feature {NONE} -- Implementation

	items: ARRAYED_QUEUE [INTEGER]
			-- The items, oldest first.

invariant
	within_capacity: count <= capacity

end
