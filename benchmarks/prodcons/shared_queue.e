note
	description: "The unbounded queue shared by the producers and consumers of the prodcons benchmark."

class
	SHARED_QUEUE

create
	make

feature {NONE} -- Initialization

	make
			-- Empty queue.
		do
			create items.make
		ensure
			empty: is_empty
		end

feature -- Access

	item: INTEGER
			-- The oldest value.
		require
			not_empty: not is_empty
		do
			Result := items.item
		end

feature -- Status report

	is_empty: BOOLEAN
			-- Is there no value?
		do
			Result := items.is_empty
		end

feature -- Element change

	extend (v: INTEGER)
			-- Append `v'.
		do
			items.extend (v)
		end

	remove
			-- Remove the oldest value.
		require
			not_empty: not is_empty
		do
			items.remove
		end

feature {NONE} -- Implementation

	items: LINKED_QUEUE [INTEGER]
			-- The values, oldest first.

end
