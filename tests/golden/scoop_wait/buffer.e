class
	BUFFER

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER)
		do
			capacity := n
			create items.make (n)
		end

feature -- Access

	capacity: INTEGER

	count: INTEGER
		do
			Result := items.count
		end

	largest_count: INTEGER
			-- Largest `count' ever seen.

	item: INTEGER
		require
			not_empty: not is_empty
		do
			Result := items.item
		end

	is_empty: BOOLEAN
		do
			Result := items.is_empty
		end

	is_full: BOOLEAN
		do
			Result := count = capacity
		end

feature -- Change

	put (v: INTEGER)
		require
			not_full: not is_full
		do
			items.extend (v)
			largest_count := largest_count.max (count)
		end

	remove
		require
			not_empty: not is_empty
		do
			items.remove
		end

feature {NONE} -- Implementation

	items: ARRAYED_QUEUE [INTEGER]

invariant
	within_capacity: count <= capacity

end
