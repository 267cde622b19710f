note
	description: "Queues stored in a circular block of memory that grows as needed."

class
	ARRAYED_QUEUE [G]

inherit
	QUEUE [G]
		redefine
			copy,
			is_equal
		end

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER_32)
			-- Make an empty queue with room for `n' items.
		require
			non_negative_argument: n >= 0
		do
			create area.make_empty (n)
			out_index := 0
			count := 0
		ensure
			capacity_expected: capacity = n
			is_empty: is_empty
		end

feature -- Access

	item: G
			-- The oldest item.
		do
			Result := area.item (out_index)
		end

	has (v: G): BOOLEAN
			-- <Precursor>
		local
			i, j: INTEGER_32
		do
			from
				i := out_index
			until
				j >= count or Result
			loop
				Result := same_item (area.item (i), v)
				i := next_position (i)
				j := j + 1
			end
		end

feature -- Measurement

	count: INTEGER_32
			-- <Precursor>

	capacity: INTEGER_32
			-- Number of items the queue holds before its storage grows.
		do
			Result := area.capacity
		end

	occurrences (v: G): INTEGER_32
			-- <Precursor>
		local
			i, j: INTEGER_32
		do
			from
				i := out_index
			until
				j >= count
			loop
				if same_item (area.item (i), v) then
					Result := Result + 1
				end
				i := next_position (i)
				j := j + 1
			end
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the current queue and `other' hold the same items in the same order,
			-- with the same comparison criterion?
		local
			i, j, k: INTEGER_32
		do
			if count = other.count and object_comparison = other.object_comparison then
				from
					Result := True
					i := out_index
					j := other.out_index
				until
					k >= count or not Result
				loop
					Result := same_item (area.item (i), other.area.item (j))
					i := next_position (i)
					j := other.next_position (j)
					k := k + 1
				end
			end
		end

feature -- Status report

	prunable: BOOLEAN
			-- May items be removed with `prune'? (No: only `remove' takes items out.)
		do
			Result := False
		end

feature -- Element change

	extend, put, force (v: G)
			-- Add `v' as the newest item.
		local
			i: INTEGER_32
		do
			if count >= area.capacity then
				grow (area.capacity + additional_space)
			end
			i := in_position
			if i = area.count then
				area.extend (v)
			else
				area.put (v, i)
			end
			count := count + 1
		end

	replace (v: G)
			-- Put `v' in place of the oldest item.
		do
			area.put (v, out_index)
		end

feature -- Removal

	remove
			-- Remove the oldest item.
		require else
			writable: writable
		local
			removed: INTEGER_32
		do
			removed := out_index
			out_index := next_position (out_index)
			count := count - 1
			if count = 0 then
				wipe_out
			else
				area.put (area.item (last_position), removed)
			end
		end

	wipe_out
			-- Remove every item.
		require else
			always: True
		do
			area.wipe_out
			out_index := 0
			count := 0
		end

feature -- Conversion

	linear_representation: ARRAYED_LIST [G]
			-- The items, from the oldest to the newest.
		local
			i, j: INTEGER_32
		do
			from
				create Result.make (count)
				i := out_index
			until
				j >= count
			loop
				Result.extend (area.item (i))
				i := next_position (i)
				j := j + 1
			end
		end

feature -- Duplication

	copy (other: like Current)
			-- Take the items of `other', in storage of its own.
		do
			if other /= Current then
				standard_copy (other)
				area := other.area.twin
			end
		end

feature {ARRAYED_QUEUE} -- Implementation

	area: SPECIAL [G]
			-- The storage, used as a ring.

	out_index: INTEGER_32
			-- Index in `area' of the oldest item.

	next_position (i: INTEGER_32): INTEGER_32
			-- Index in `area' following `i', wrapping around.
		do
			Result := i + 1
			if Result >= area.capacity then
				Result := 0
			end
		end

feature {NONE} -- Implementation

	in_position: INTEGER_32
			-- Index in `area' for the next item.
		do
			if area.capacity > 0 then
				Result := (out_index + count) \\ area.capacity
			end
		end

	last_position: INTEGER_32
			-- Index in `area' of the newest item.
		require
			not_empty: count > 0
		do
			Result := (out_index + count - 1) \\ area.capacity
		end

	additional_space: INTEGER_32
			-- Extra room added when the storage grows.
		do
			Result := (area.capacity // 2).max (5)
		end

	grow (n: INTEGER_32)
			-- Make room for `n' items, keeping them in order from index 0.
			-- (Two block copies, no loop: `extend' stays a short routine that a client may run.)
		local
			new_area: SPECIAL [G]
			first: INTEGER_32
		do
			create new_area.make_empty (n.max (count))
			first := (area.count - out_index).min (count)
			if first > 0 then
				new_area.copy_data (area, out_index, 0, first)
			end
			if count > first then
				new_area.copy_data (area, 0, first, count - first)
			end
			area := new_area
			out_index := 0
		end

	same_item (a, b: G): BOOLEAN
			-- Are `a' and `b' the same item for searches?
		do
			if object_comparison then
				Result := a ~ b
			else
				Result := a = b
			end
		end

invariant
	count_in_bounds: 0 <= count and count <= area.capacity

end
