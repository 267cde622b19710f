note
	description: "[
		Sets of comparable items, searched by halving: `extend' (and `put') add an item
		only if the set does not hold it yet (compared with `=', or `~' after
		`compare_objects'); the internal cursor (`start', `item', `forth', `after') and
		`across' visit the items from the smallest to the largest.
	]"
	implementation: "[
		An ARRAYED_LIST kept in increasing order, searched by bisection (EiffelBase uses a
		binary search tree; the observable order and contents are the same).
	]"

class
	BINARY_SEARCH_TREE_SET [G -> COMPARABLE]

inherit
	COLLECTION [G]
		redefine
			copy,
			is_equal
		end

	ITERABLE [G]
		redefine
			copy,
			is_equal
		end

create
	make,
	make_from_iterable

feature {NONE} -- Initialization

	make
			-- An empty set, the cursor `before' its items.
		do
			create items.make (0)
			index := 0
		ensure
			is_empty: is_empty
			is_before: before
		end

	make_from_iterable (other: ITERABLE [G])
			-- A set of the items of `other'.
		do
			make
			across other as c loop
				extend (c.item)
			end
		end

feature -- Access

	item: G
			-- Item at the cursor.
		require
			not_off: not off
		do
			Result := items.i_th (index)
		end

	min: G
			-- Smallest item.
		require
			not_empty: not is_empty
		do
			Result := items.first
		end

	max: G
			-- Largest item.
		require
			not_empty: not is_empty
		do
			Result := items.last
		end

	has (v: G): BOOLEAN
			-- Is `v' in the set?
			-- (Compared with `=' or `~' according to `object_comparison'.)
		do
			Result := position_of (v) > 0
		end

	new_cursor: ITERATION_CURSOR [G]
			-- A cursor on the smallest item.
		do
			Result := items.new_cursor
		end

feature -- Measurement

	count: INTEGER_32
			-- Number of items.
		do
			Result := items.count
		end

feature -- Status report

	extendible: BOOLEAN = True
			-- May items be added? (Yes.)

	prunable: BOOLEAN = True
			-- May items be removed? (Yes.)

	before: BOOLEAN
			-- Is the cursor before the smallest item?
		do
			Result := index = 0
		end

	after: BOOLEAN
			-- Is the cursor past the largest item?
		do
			Result := index = count + 1
		end

	off: BOOLEAN
			-- Is there no item at the cursor?
		do
			Result := before or after
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the set and `other' hold the same items, with the same comparison criterion?
		local
			i: INTEGER_32
		do
			if other = Current then
				Result := True
			elseif count = other.count and object_comparison = other.object_comparison then
				from
					Result := True
					i := 1
				until
					not Result or i > count
				loop
					if object_comparison then
						Result := items.i_th (i) ~ other.items.i_th (i)
					else
						Result := items.i_th (i) = other.items.i_th (i)
					end
					i := i + 1
				end
			end
		end

	is_subset (other: CONTAINER [G]): BOOLEAN
			-- Is every item of the set in `other'?
		do
			Result := across items as c all other.has (c.item) end
		end

	is_superset (other: CONTAINER [G]): BOOLEAN
			-- Is every item of `other' in the set?
		do
			Result := across other.linear_representation as c all has (c.item) end
		end

	disjoint (other: CONTAINER [G]): BOOLEAN
			-- Do the set and `other' have no item in common?
		do
			Result := across items as c all not other.has (c.item) end
		end

feature -- Cursor movement

	start
			-- Move the cursor to the smallest item (`after' if the set is empty).
		do
			index := 1
		ensure
			empty_convention: is_empty implies after
		end

	finish
			-- Move the cursor to the largest item (`before' if the set is empty).
		do
			index := count
		ensure
			empty_convention: is_empty implies before
		end

	forth
			-- Move the cursor to the next larger item.
		require
			not_after: not after
		do
			index := index + 1
		end

	back
			-- Move the cursor to the next smaller item.
		require
			not_before: not before
		do
			index := index - 1
		end

feature -- Element change

	extend, put (v: G)
			-- Add `v' at its place in the order unless the set holds it already.
			-- The cursor stays on the same item.
		local
			i: INTEGER_32
		do
			if position_of (v) = 0 then
				from
					i := lower_position (v)
				until
					i > count or else v < items.i_th (i)
				loop
					i := i + 1
				end
				items.go_i_th (i)
				items.put_left (v)
				if index > 0 and i <= index then
					index := index + 1
				end
			end
		ensure then
			in_set: has (v)
		end

	merge (other: CONTAINER [G])
			-- Add every item of `other' that is not in the set yet.
		do
			across other.linear_representation as c loop
				extend (c.item)
			end
		end

feature -- Removal

	prune (v: G)
			-- Remove `v' if it is in the set. A cursor on it moves to the next item.
		local
			i: INTEGER_32
		do
			i := position_of (v)
			if i > 0 then
				remove_at (i)
			end
		ensure then
			not_in_set: not has (v)
		end

	remove
			-- Remove the item at the cursor; the cursor moves to the next item.
		require
			not_off: not off
		do
			remove_at (index)
		end

	wipe_out
			-- Remove every item; the cursor goes `before'.
		do
			items.wipe_out
			index := 0
		end

	intersect (other: CONTAINER [G])
			-- Keep only the items that are also in `other'.
		local
			i: INTEGER_32
		do
			from
				i := 1
			until
				i > count
			loop
				if other.has (items.i_th (i)) then
					i := i + 1
				else
					remove_at (i)
				end
			end
		end

	subtract (other: CONTAINER [G])
			-- Remove the items that are also in `other'.
		local
			i: INTEGER_32
		do
			from
				i := 1
			until
				i > count
			loop
				if other.has (items.i_th (i)) then
					remove_at (i)
				else
					i := i + 1
				end
			end
		end

	symdif (other: CONTAINER [G])
			-- Remove the items that are also in `other' and add those of `other' that were not in the set.
		local
			l_other: ARRAYED_LIST [G]
		do
			create l_other.make (0)
			across other.linear_representation as c loop
				l_other.extend (c.item)
			end
			across l_other as c loop
				if has (c.item) then
					prune (c.item)
				else
					extend (c.item)
				end
			end
		end

feature -- Iteration

	do_all (action: PROCEDURE [TUPLE [G]])
			-- Apply `action' to every item, from the smallest to the largest.
		do
			items.do_all (action)
		end

	do_if (action: PROCEDURE [TUPLE [G]]; test: FUNCTION [TUPLE [G], BOOLEAN])
			-- Apply `action' to every item that satisfies `test', from the smallest to the largest.
		do
			items.do_if (action, test)
		end

	there_exists (test: FUNCTION [TUPLE [G], BOOLEAN]): BOOLEAN
			-- Does `test' hold for at least one item?
		do
			Result := items.there_exists (test)
		end

	for_all (test: FUNCTION [TUPLE [G], BOOLEAN]): BOOLEAN
			-- Does `test' hold for every item?
		do
			Result := items.for_all (test)
		end

feature -- Conversion

	linear_representation: LINEAR [G]
			-- The items in increasing order, in a new list.
		do
			Result := items.twin
		end

feature -- Duplication

	copy (other: like Current)
			-- Take the items, cursor and comparison criterion of `other', in storage of its own.
		do
			if other /= Current then
				standard_copy (other)
				items := other.items.twin
			end
		end

feature {BINARY_SEARCH_TREE_SET} -- Implementation

	items: ARRAYED_LIST [G]
			-- The items, in increasing order.

feature {NONE} -- Implementation

	index: INTEGER_32
			-- Position of the cursor in `items' (0: `before', `count' + 1: `after').

	lower_position (v: G): INTEGER_32
			-- Position of the first item not smaller than `v' (`count' + 1 if there is none).
		local
			l_low, l_high, l_middle: INTEGER_32
		do
			from
				l_low := 1
				l_high := count + 1
			until
				l_low >= l_high
			loop
				l_middle := (l_low + l_high) // 2
				if items.i_th (l_middle) < v then
					l_low := l_middle + 1
				else
					l_high := l_middle
				end
			end
			Result := l_low
		ensure
			in_range: Result >= 1 and Result <= count + 1
		end

	position_of (v: G): INTEGER_32
			-- Position of the item that is `v' for the comparison criterion, 0 if there is none.
		local
			i: INTEGER_32
			l_item: G
		do
			from
				i := lower_position (v)
			until
				Result > 0 or i > count
			loop
				l_item := items.i_th (i)
				if v < l_item then
					i := count + 1
				else
					if object_comparison then
						if l_item ~ v then
							Result := i
						end
					elseif l_item = v then
						Result := i
					end
					i := i + 1
				end
			end
		ensure
			non_negative: Result >= 0
		end

	remove_at (i: INTEGER_32)
			-- Remove the item at position `i'; the cursor stays on its item (or moves
			-- to the next one if it was on the removed one).
		require
			valid_position: i >= 1 and i <= count
		do
			items.go_i_th (i)
			items.remove
			if i < index then
				index := index - 1
			end
		end

invariant
	index_in_range: index >= 0 and index <= count + 1

end
