note
	description: "[
		Priority queues stored as binary heaps: `item' is the largest item and
		`remove' takes it out, both in logarithmic time. Traversal follows the heap's
		internal order, not the priority order.
	]"

class
	HEAP_PRIORITY_QUEUE [G -> COMPARABLE]

inherit
	PRIORITY_QUEUE [G]
		redefine
			copy,
			is_equal
		end

create
	make,
	make_from_iterable

feature {NONE} -- Initialization

	make (n: INTEGER_32)
			-- Make an empty queue with room for `n' items.
		require
			non_negative_argument: n >= 0
		do
			create area.make_empty (n)
		ensure
			is_empty: is_empty
		end

	make_from_iterable (other: ITERABLE [G])
			-- Make a queue of the items of `other'.
		do
			make (0)
			across other as c loop
				extend (c.item)
			end
		end

feature -- Access

	item: G
			-- The largest item.
		do
			Result := area.item (0)
		end

	has (v: G): BOOLEAN
			-- <Precursor>
		local
			i: INTEGER_32
		do
			from
			until
				Result or i >= area.count
			loop
				Result := same_item (area.item (i), v)
				i := i + 1
			end
		end

feature -- Measurement

	count: INTEGER_32
			-- <Precursor>
		do
			Result := area.count
		end

	capacity: INTEGER_32
			-- Number of items the queue holds before its storage grows.
		do
			Result := area.capacity
		end

	occurrences (v: G): INTEGER_32
			-- <Precursor>
		local
			i: INTEGER_32
		do
			from
			until
				i >= area.count
			loop
				if same_item (area.item (i), v) then
					Result := Result + 1
				end
				i := i + 1
			end
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the current queue and `other' hold the same items in the same heap order?
		do
			Result := object_comparison = other.object_comparison and then count = other.count
				and then area.same_items (other.area, 0, 0, count)
		end

feature -- Status report

	prunable: BOOLEAN
			-- May items be removed? (Yes.)
		do
			Result := True
		end

feature -- Element change

	extend, put, force (v: G)
			-- Add `v'.
		local
			i: INTEGER_32
		do
			if area.count + 1 > area.capacity then
				area := area.aliased_resized_area (area.count + 1 + (area.capacity // 2).max (5))
			end
			area.extend (v)
			from
				i := area.count
			until
				i <= 1 or else not (area.item (i // 2 - 1) < v)
			loop
				area.put (area.item (i // 2 - 1), i - 1)
				i := i // 2
			end
			area.put (v, i - 1)
		end

	replace (v: G)
			-- Put `v' in place of the largest item, then restore the order.
		do
			remove
			extend (v)
		end

feature -- Removal

	remove
			-- Remove the largest item.
		local
			i, j, n: INTEGER_32
			up: G
			stop: BOOLEAN
		do
			n := area.count - 1
			up := area.item (n)
			area.remove_tail (1)
			if n > 0 then
				from
					i := 1
				until
					stop or 2 * i > n
				loop
					j := 2 * i
					if j < n and then area.item (j - 1) < area.item (j) then
						j := j + 1
					end
					stop := not (up < area.item (j - 1))
					if not stop then
						area.put (area.item (j - 1), i - 1)
						i := j
					end
				end
				area.put (up, i - 1)
			end
		end

	wipe_out
			-- Remove every item.
		do
			area.wipe_out
		end

feature -- Conversion

	linear_representation: ARRAYED_LIST [G]
			-- The items, in the heap's order.
		local
			i: INTEGER_32
		do
			from
				create Result.make (count)
			until
				i >= area.count
			loop
				Result.extend (area.item (i))
				i := i + 1
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

feature {HEAP_PRIORITY_QUEUE} -- Implementation

	area: SPECIAL [G]
			-- The heap: the children of the item at position i (counting from 1) are at 2i and 2i + 1.

feature {NONE} -- Implementation

	same_item (a, b: G): BOOLEAN
			-- Are `a' and `b' the same item for searches?
		do
			if object_comparison then
				Result := a ~ b
			else
				Result := a = b
			end
		end

end
