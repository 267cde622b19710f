note
	description: "A bounded first-in first-out buffer of range readings, kept in a ring."

class
	SCAN_BUFFER

create
	make

feature {NONE} -- Initialization

	make (a_capacity: INTEGER)
			-- Empty buffer for at most `a_capacity' readings.
		require
			positive_capacity: a_capacity > 0
		do
			create slots.make_filled (0, 0, a_capacity - 1)
		ensure
			empty: is_empty
			capacity_set: capacity = a_capacity
		end

feature -- Access

	item: INTEGER
			-- The oldest reading.
		require
			not_empty: not is_empty
		do
			Result := slots.item (head)
		end

	count: INTEGER
			-- Readings held.

	capacity: INTEGER
			-- Readings the buffer can hold.
		do
			Result := slots.count
		end

feature -- Status report

	is_empty: BOOLEAN
			-- Is there no reading?
		do
			Result := count = 0
		end

	is_full: BOOLEAN
			-- Is there no room left?
		do
			Result := count = capacity
		end

feature -- Element change

	put (a_reading: INTEGER)
			-- Append `a_reading'.
		require
			not_full: not is_full
		do
			slots.put (a_reading, (head + count) \\ capacity)
			count := count + 1
		ensure
			one_more: count = old count + 1
		end

	remove
			-- Remove the oldest reading.
		require
			not_empty: not is_empty
		do
			head := (head + 1) \\ capacity
			count := count - 1
		ensure
			one_less: count = old count - 1
		end

feature {NONE} -- Implementation

	slots: ARRAY [INTEGER]
			-- Storage, indexed from 0.

	head: INTEGER
			-- Index of the oldest reading in `slots'.

invariant
	count_in_bounds: 0 <= count and count <= capacity
	head_in_bounds: 0 <= head and head < capacity

end
