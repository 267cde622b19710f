note
	description: "[
		Lists stored in a resizable block of memory: fast access by index and at the
		end, slower insertion and removal elsewhere. The cursor is the number `index':
		items inserted at the end while the cursor is `after' become the current item.
	]"

class
	ARRAYED_LIST [G]

inherit
	DYNAMIC_LIST [G]
		redefine
			copy,
			is_equal
		end

create
	make,
	make_filled,
	make_from_array,
	make_from_iterable

feature {NONE} -- Initialization

	make (n: INTEGER_32)
			-- Make an empty list with room for `n' items.
		require
			valid_number_of_items: n >= 0
		do
			index := 0
			create area.make_empty (n)
		ensure
			correct_position: before
			is_empty: is_empty
		end

	make_filled (n: INTEGER_32)
			-- Make a list of `n' items with the default value of G.
		require
			valid_number_of_items: n >= 0
		do
			index := 0
			create area.make_empty (n)
			area.fill_with_default (0, n - 1)
		ensure
			correct_position: before
			filled: count = n
		end

	make_from_array (a: ARRAY [G])
			-- Make a list of the items of `a', sharing its storage.
		do
			index := 0
			area := a.area
		ensure
			correct_position: before
			filled: count = a.count
		end

	make_from_iterable (other: ITERABLE [G])
			-- Make a list of the items of `other', in order.
		do
			make (0)
			across other as c loop
				extend (c.item)
			end
		end

feature -- Access

	item: G
			-- <Precursor>
		require else
			index_is_valid: valid_index (index)
		do
			Result := area.item (index - 1)
		end

	i_th alias "[]", at alias "@" (i: INTEGER_32): G assign put_i_th
			-- <Precursor>
		do
			Result := area.item (i - 1)
		end

	index: INTEGER_32
			-- <Precursor>

	area: SPECIAL [G]
			-- The storage of the items.

	cursor: ARRAYED_LIST_CURSOR
			-- <Precursor>
		do
			create Result.make (index)
		end

	new_cursor: ARRAYED_LIST_ITERATION_CURSOR [G]
			-- <Precursor>
		do
			create Result.make (Current)
			Result.start
		end

feature -- Measurement

	count: INTEGER_32
			-- <Precursor>
		do
			Result := area.count
		end

	capacity: INTEGER_32
			-- Number of items the list can hold before its storage grows.
		do
			Result := area.capacity
		end

	upper: INTEGER_32
			-- Index of the last item.
		do
			Result := area.count
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the current list and `other' hold the same items, with the same comparison criterion?
		local
			i, n: INTEGER_32
		do
			if other = Current then
				Result := True
			elseif count = other.count and object_comparison = other.object_comparison then
				from
					Result := True
					n := count
				until
					not Result or i >= n
				loop
					Result := same_item (area.item (i), other.area.item (i))
					i := i + 1
				end
			end
		end

feature -- Status report

	valid_cursor (p: CURSOR): BOOLEAN
			-- <Precursor>
		do
			Result := attached {ARRAYED_LIST_CURSOR} p as c and then valid_cursor_index (c.index)
		end

	full: BOOLEAN
			-- Is the storage full (the next `extend' grows it)?
		do
			Result := count = capacity
		end

feature -- Cursor movement

	start
			-- <Precursor>
		do
			index := 1
		ensure then
			after_when_empty: is_empty implies after
		end

	finish
			-- <Precursor>
		do
			index := count
		ensure then
			before_when_empty: is_empty implies before
		end

	forth
			-- <Precursor>
		do
			index := index + 1
		end

	back
			-- <Precursor>
		do
			index := index - 1
		end

	go_i_th (i: INTEGER_32)
			-- <Precursor>
		do
			index := i
		end

	go_to (p: CURSOR)
			-- <Precursor>
		do
			if attached {ARRAYED_LIST_CURSOR} p as c then
				index := c.index
			end
		end

feature -- Element change

	extend (v: G)
			-- Add `v' at the end; the cursor does not move.
		do
			append_item (v)
		end

	put_front (v: G)
			-- <Precursor>
		do
			if is_empty then
				append_item (v)
			else
				insert (v, 1)
			end
			index := index + 1
		end

	put_left (v: G)
			-- <Precursor>
		do
			if after or is_empty then
				append_item (v)
			else
				insert (v, index)
			end
			index := index + 1
		end

	put_right (v: G)
			-- <Precursor>
		do
			if index = count then
				append_item (v)
			else
				insert (v, index + 1)
			end
		end

	replace (v: G)
			-- <Precursor>
		do
			area.put (v, index - 1)
		end

	put_i_th (v: G; i: INTEGER_32)
			-- <Precursor>
		do
			area.put (v, i - 1)
		end

feature -- Removal

	remove
			-- Remove the current item; the cursor moves to the next one (or `after').
		do
			if index < count then
				area.move_data (index, index - 1, count - index)
			end
			area.remove_tail (1)
		ensure then
			same_index: index = old index
		end

	remove_left
			-- <Precursor>
		do
			index := index - 1
			remove
		end

	remove_right
			-- <Precursor>
		do
			index := index + 1
			remove
			index := index - 1
		end

	wipe_out
			-- <Precursor>
		do
			area.wipe_out
			index := 0
		end

feature -- Resizing

	grow (i: INTEGER_32)
			-- Make room for at least `i' items.
		do
			if i > area.capacity then
				area := area.aliased_resized_area (i)
			end
		ensure
			large_enough: capacity >= i
		end

	resize (new_capacity: INTEGER_32)
			-- Make room for at least `new_capacity' items.
		require
			new_capacity_large_enough: new_capacity >= capacity
		do
			grow (new_capacity)
		ensure
			capacity_set: capacity >= new_capacity
		end

	trim
			-- Make the capacity equal to `count'.
		do
			if count < area.capacity then
				area := area.aliased_resized_area (count)
			end
		ensure
			same_count: count = old count
		end

feature -- Conversion

	to_array: ARRAY [G]
			-- An array indexed from 1, sharing the storage of the list.
		do
			create Result.make_from_special (area)
		ensure
			lower_set: Result.lower = 1
			upper_set: Result.upper = count
		end

feature -- Duplication

	copy (other: like Current)
			-- Take the items and cursor position of `other', in storage of its own.
		do
			if other /= Current then
				standard_copy (other)
				area := other.area.twin
			end
		end

	duplicate (n: INTEGER_32): like Current
			-- <Precursor>
		local
			l_count: INTEGER_32
		do
			if after then
				create Result.make (0)
			else
				l_count := n.min (count - index + 1)
				create Result.make (l_count)
				Result.area.copy_data (area, index - 1, 0, l_count)
			end
		end

feature {NONE} -- Implementation

	additional_space: INTEGER_32
			-- Extra room added when the storage grows.
		do
			Result := (area.capacity // 2).max (5)
		end

	append_item (v: G)
			-- Add `v' at the end, growing the storage if needed.
		do
			if count + 1 > area.capacity then
				area := area.aliased_resized_area (count + 1 + additional_space)
			end
			area.extend (v)
		end

	insert (v: G; pos: INTEGER_32)
			-- Put `v' at position `pos', moving the items from `pos' on one place to the right.
		require
			valid_position: 1 <= pos and pos <= count
		local
			n: INTEGER_32
		do
			n := count - pos
			if count + 1 > area.capacity then
				area := area.aliased_resized_area (count + 1 + additional_space)
			end
			area.extend (area.item (count - 1))
			area.move_data (pos - 1, pos, n)
			area.put (v, pos - 1)
		end

invariant
	index_in_bounds: 0 <= index and index <= count + 1

end
