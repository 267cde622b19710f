note
	description: "Stacks stored in a resizable block of memory, the top at the end."

class
	ARRAYED_STACK [G]

inherit
	STACK [G]
		redefine
			copy,
			is_equal
		end

create
	make,
	make_from_iterable

feature {NONE} -- Initialization

	make (n: INTEGER_32)
			-- Make an empty stack with room for `n' items.
		require
			non_negative_argument: n >= 0
		do
			create area.make_empty (n)
		ensure
			is_empty: is_empty
		end

	make_from_iterable (other: ITERABLE [G])
			-- Make a stack by pushing the items of `other' in order (the last one on top).
		do
			make (0)
			across other as c loop
				extend (c.item)
			end
		end

feature -- Access

	item: G
			-- The top item.
		do
			Result := area.item (area.count - 1)
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
			-- Number of items the stack holds before its storage grows.
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
			-- Do the current stack and `other' hold the same items in the same order,
			-- with the same comparison criterion?
		local
			i: INTEGER_32
		do
			if count = other.count and object_comparison = other.object_comparison then
				from
					Result := True
				until
					not Result or i >= count
				loop
					Result := same_item (area.item (i), other.area.item (i))
					i := i + 1
				end
			end
		end

feature -- Status report

	prunable: BOOLEAN
			-- May items be removed? (Yes.)
		do
			Result := True
		end

feature -- Element change

	extend, put, force (v: G)
			-- Push `v' on top.
		do
			if area.count + 1 > area.capacity then
				area := area.aliased_resized_area (area.count + 1 + (area.capacity // 2).max (5))
			end
			area.extend (v)
		end

	replace (v: G)
			-- Put `v' in place of the top item.
		do
			area.put (v, area.count - 1)
		end

feature -- Removal

	remove
			-- Pop the top item.
		do
			area.remove_tail (1)
		end

	wipe_out
			-- Remove every item.
		do
			area.wipe_out
		end

feature -- Conversion

	linear_representation: ARRAYED_LIST [G]
			-- The items, from the top to the bottom.
		local
			i: INTEGER_32
		do
			from
				create Result.make (count)
				i := area.count - 1
			until
				i < 0
			loop
				Result.extend (area.item (i))
				i := i - 1
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

feature {ARRAYED_STACK} -- Implementation

	area: SPECIAL [G]
			-- The items, from the bottom to the top.

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
