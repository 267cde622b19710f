note
	description: "[
		Sequences of items indexed by the integers of an interval `lower' .. `upper'
		(1 .. n unless chosen otherwise). `force' and the `resize' routines move the
		bounds; `item' and `put' require a valid index. Manifest arrays << a, b >> are
		ARRAYs indexed from 1.
	]"
	implementation: "[
		Items live in `area' (a SPECIAL), the one at `lower' at index 0. Creating or
		growing an array without giving a value fills the new slots with the default
		value of G (`make', `make_filled' of ARRAYED_LIST, `force' past the ends, `resize',
		`grow'); EiffelBase requires G to have a default value there and so should
		programs.
	]"

class
	ARRAY [G]

inherit
	FINITE [G]
		redefine
			copy,
			is_equal
		end

	READABLE_INDEXABLE [G]
		redefine
			copy,
			is_equal,
			new_cursor
		end

create
	make_empty,
	make,
	make_filled,
	make_from_array,
	make_from_special

feature -- Initialization

	make_empty
			-- Make an empty array with bounds 1 .. 0.
		do
			lower := 1
			upper := 0
			create area.make_empty (0)
		ensure
			lower_set: lower = 1
			upper_set: upper = 0
		end

	make (min_index, max_index: INTEGER_32)
			-- Make an array indexed from `min_index' to `max_index' holding default values
			-- (empty if `min_index' = `max_index' + 1).
		require
			valid_bounds: min_index <= max_index + 1
		local
			n: INTEGER_32
		do
			lower := min_index
			upper := max_index
			n := max_index - min_index + 1
			create area.make_empty (n)
			area.fill_with_default (0, n - 1)
		ensure
			lower_set: lower = min_index
			upper_set: upper = max_index
		end

	make_filled (a_default_value: G; min_index, max_index: INTEGER_32)
			-- Make an array indexed from `min_index' to `max_index' with every item
			-- equal to `a_default_value'.
		require
			valid_bounds: min_index <= max_index + 1
		do
			lower := min_index
			upper := max_index
			create area.make_filled (a_default_value, max_index - min_index + 1)
		ensure
			lower_set: lower = min_index
			upper_set: upper = max_index
			filled: filled_with (a_default_value)
		end

	make_from_array (a: ARRAY [G])
			-- Make an array with the bounds of `a', sharing its items.
		do
			area := a.area
			lower := a.lower
			upper := a.upper
		ensure
			shared: area = a.area
			lower_set: lower = a.lower
			upper_set: upper = a.upper
		end

	make_from_special (a: SPECIAL [G])
			-- Make an array indexed from 1 sharing the items of `a'.
		do
			area := a
			lower := 1
			upper := a.count
		ensure
			shared: area = a
			lower_set: lower = 1
			upper_set: upper = a.count
		end

feature -- Access

	item alias "[]", at alias "@" (i: INTEGER_32): G assign put
			-- Item at index `i'.
		require
			valid_key: valid_index (i)
		external
			"Python"
				-- `Result := area.item (i - lower)', without the calls (scoopc/kernel/ext/array.py)
		end

	has (v: G): BOOLEAN
			-- <Precursor>
		local
			i, n: INTEGER_32
		do
			from
				n := count
			until
				i >= n or Result
			loop
				Result := same_item (area.item (i), v)
				i := i + 1
			end
		end

	area: SPECIAL [G]
			-- The storage of the items.

	to_special: SPECIAL [G]
			-- The storage of the items (shared).
		do
			Result := area
		end

	new_cursor: ARRAY_ITERATION_CURSOR [G]
			-- <Precursor>
		do
			create Result.make (Current)
			Result.start
		end

feature -- Measurement

	lower: INTEGER_32
			-- Smallest index.

	upper: INTEGER_32
			-- Largest index.

	count, capacity: INTEGER_32
			-- Number of indices, `upper' - `lower' + 1.
		do
			Result := upper - lower + 1
		end

	occurrences (v: G): INTEGER_32
			-- Number of times `v' occurs.
			-- (Compared with `=' or `~' according to `object_comparison'.)
		local
			i, n: INTEGER_32
		do
			from
				n := count
			until
				i >= n
			loop
				if same_item (area.item (i), v) then
					Result := Result + 1
				end
				i := i + 1
			end
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the current array and `other' have the same bounds, the same
			-- comparison criterion and the same items?
		local
			i: INTEGER_32
		do
			if other = Current then
				Result := True
			elseif lower = other.lower and upper = other.upper and object_comparison = other.object_comparison then
				from
					Result := True
					i := lower
				until
					not Result or i > upper
				loop
					Result := same_item (item (i), other.item (i))
					i := i + 1
				end
			end
		end

	same_items (other: like Current): BOOLEAN
			-- Do the current array and `other' hold the same items (`='), whatever their bounds?
		do
			Result := count = other.count and then area.same_items (other.area, 0, 0, count)
		end

feature -- Status report

	valid_index (i: INTEGER_32): BOOLEAN
			-- Is `i' between `lower' and `upper'?
		do
			Result := lower <= i and i <= upper
		end

	filled_with (v: G): BOOLEAN
			-- Are all items equal (`=') to `v'?
		do
			Result := area.filled_with (v, 0, count - 1)
		end

	full: BOOLEAN
			-- Is every index used? (Yes.)
		do
			Result := True
		end

feature -- Element change

	put (v: G; i: INTEGER_32)
			-- Put `v' at index `i'.
		require
			valid_key: valid_index (i)
		external
			"Python"
				-- `area.put (v, i - lower)', without the calls (scoopc/kernel/ext/array.py)
		ensure
			inserted: item (i) = v
		end

	enter (v: G; i: INTEGER_32)
			-- Put `v' at index `i'.
		require
			valid_key: valid_index (i)
		do
			area.put (v, i - lower)
		end

	force (v: G; i: INTEGER_32)
			-- Put `v' at index `i', first moving the bounds to include `i' if needed;
			-- new slots between the old bounds and `i' get the default value of G.
		local
			new_lower, new_upper, new_count, n: INTEGER_32
			new_area: SPECIAL [G]
		do
			if valid_index (i) then
				area.put (v, i - lower)
			else
				n := count
				new_lower := lower.min (i)
				new_upper := upper.max (i)
				new_count := new_upper - new_lower + 1
				if i > upper then
					if new_count > area.capacity then
						area := area.aliased_resized_area (new_count.max (area.capacity + additional_space))
					end
					area.fill_with_default (n, new_count - 2)
					area.extend (v)
				else
					create new_area.make_empty (new_count.max (area.capacity))
					new_area.extend (v)
					new_area.fill_with_default (1, lower - i - 1)
					new_area.copy_data (area, 0, lower - i, n)
					area := new_area
				end
				lower := new_lower
				upper := new_upper
			end
		ensure
			inserted: item (i) = v
			higher_count: count >= old count
			lower_set: lower = (old lower).min (i)
			upper_set: upper = (old upper).max (i)
		end

	fill_with (v: G)
			-- Put `v' at every index.
		do
			area.fill_with (v, 0, count - 1)
		ensure
			same_count: count = old count
			filled: filled_with (v)
		end

	subcopy (other: ARRAY [G]; start_pos, end_pos, index_pos: INTEGER_32)
			-- Copy the items of `other' from `start_pos' to `end_pos' here, from `index_pos' on.
		require
			valid_start_pos: start_pos >= other.lower
			valid_end_pos: end_pos <= other.upper
			valid_bounds: start_pos <= end_pos + 1
			valid_index_pos: index_pos >= lower
			enough_space: (upper - index_pos) >= (end_pos - start_pos)
		do
			area.copy_data (other.area, start_pos - other.lower, index_pos - lower, end_pos - start_pos + 1)
		end

feature -- Resizing

	rebase (a_lower: INTEGER_32)
			-- Shift the bounds so that `lower' becomes `a_lower'; the items do not change.
		do
			upper := a_lower + count - 1
			lower := a_lower
		ensure
			lower_set: lower = a_lower
			same_count: count = old count
		end

	conservative_resize_with_default (a_default_value: G; min_index, max_index: INTEGER_32)
			-- Move the bounds to include `min_index' and `max_index', keeping every item;
			-- new slots get `a_default_value'.
		require
			good_indices: min_index <= max_index
		local
			offset, old_count: INTEGER_32
		do
			if count = 0 then
				make_filled (a_default_value, min_index, max_index)
			else
				old_count := count
				offset := lower - min_index.min (lower)
				resize_to (min_index.min (lower), max_index.max (upper))
				area.fill_with (a_default_value, 0, offset - 1)
				area.fill_with (a_default_value, offset + old_count, count - 1)
			end
		ensure
			no_low_lost: lower = min_index.min (old lower) or (old count = 0 and lower = min_index)
			no_high_lost: upper = max_index.max (old upper) or (old count = 0 and upper = max_index)
		end

	resize (min_index, max_index: INTEGER_32)
			-- Move the bounds to include `min_index' and `max_index', keeping every item;
			-- new slots get the default value of G.
		require
			good_indices: min_index <= max_index
		do
			if count = 0 then
				make (min_index, max_index)
			else
				resize_to (min_index.min (lower), max_index.max (upper))
			end
		end

	grow (i: INTEGER_32)
			-- Make room for at least `i' items, adding indices above `upper'.
		do
			if i > count then
				if count = 0 then
					make (lower, lower + i - 1)
				else
					resize_to (lower, lower + i - 1)
				end
			end
		ensure
			large_enough: count >= i
		end

	keep_head (n: INTEGER_32)
			-- Keep only the first `n' items (all if `n' >= `count').
		require
			non_negative_argument: n >= 0
		do
			if n < count then
				area.keep_head (n)
				upper := lower + n - 1
			end
		ensure
			new_count: count = n.min (old count)
			same_lower: lower = old lower
		end

	keep_tail (n: INTEGER_32)
			-- Keep only the last `n' items (all if `n' >= `count').
		require
			non_negative_argument: n >= 0
		do
			if n < count then
				area.keep_tail (n)
				lower := upper - n + 1
			end
		ensure
			new_count: count = n.min (old count)
			same_upper: upper = old upper
		end

	remove_head (n: INTEGER_32)
			-- Remove the first `n' items (all if `n' >= `count').
		require
			non_negative_argument: n >= 0
		do
			keep_tail ((count - n).max (0))
		ensure
			same_upper: upper = old upper
		end

	remove_tail (n: INTEGER_32)
			-- Remove the last `n' items (all if `n' >= `count').
		require
			non_negative_argument: n >= 0
		do
			keep_head ((count - n).max (0))
		ensure
			same_lower: lower = old lower
		end

feature -- Removal

	discard_items, clear_all
			-- Put the default value of G at every index.
		do
			area.wipe_out
			area.fill_with_default (0, count - 1)
		ensure
			same_bounds: lower = old lower and upper = old upper
		end

	wipe_out
			-- Put the default value of G at every index (bounds unchanged).
		do
			discard_items
		end

feature -- Conversion

	subarray (start_pos, end_pos: INTEGER_32): ARRAY [G]
			-- A new array with the items from `start_pos' to `end_pos', at the same indices.
		require
			valid_start_pos: valid_index (start_pos)
			valid_end_pos: end_pos <= upper
			valid_bounds: start_pos <= end_pos + 1
		local
			a: SPECIAL [G]
			n: INTEGER_32
		do
			n := end_pos - start_pos + 1
			create a.make_empty (n)
			a.copy_data (area, start_pos - lower, 0, n)
			create Result.make_from_special (a)
			Result.rebase (start_pos)
		ensure
			lower_set: Result.lower = start_pos
			upper_set: Result.upper = end_pos
		end

	linear_representation: ARRAYED_LIST [G]
			-- A new list of the items, from `lower' to `upper'.
		local
			i, n: INTEGER_32
		do
			n := count
			create Result.make (n)
			from
			until
				i >= n
			loop
				Result.extend (area.item (i))
				i := i + 1
			end
		end

feature -- Iteration

	do_all (action: PROCEDURE [TUPLE [G]])
			-- Apply `action' to every item, from `lower' to `upper'.
		do
			area.do_all_in_bounds (action, 0, count - 1)
		end

	do_if (action: PROCEDURE [TUPLE [G]]; test: FUNCTION [TUPLE [G], BOOLEAN])
			-- Apply `action' to every item that satisfies `test', from `lower' to `upper'.
		local
			i, n: INTEGER_32
		do
			from
				n := count
			until
				i >= n
			loop
				if test.item ([area.item (i)]) then
					action.call ([area.item (i)])
				end
				i := i + 1
			end
		end

	there_exists (test: FUNCTION [TUPLE [G], BOOLEAN]): BOOLEAN
			-- Does `test' hold for at least one item?
		do
			Result := area.there_exists_in_bounds (test, 0, count - 1)
		end

	for_all (test: FUNCTION [TUPLE [G], BOOLEAN]): BOOLEAN
			-- Does `test' hold for every item?
		do
			Result := area.for_all_in_bounds (test, 0, count - 1)
		end

	do_all_with_index (action: PROCEDURE [TUPLE [G, INTEGER_32]])
			-- Apply `action' to every item and its index, from `lower' to `upper'.
		local
			i: INTEGER_32
		do
			from
				i := lower
			until
				i > upper
			loop
				action.call ([item (i), i])
				i := i + 1
			end
		end

	do_if_with_index (action: PROCEDURE [TUPLE [G, INTEGER_32]]; test: FUNCTION [TUPLE [G, INTEGER_32], BOOLEAN])
			-- Apply `action' to every item and its index that satisfy `test'.
		local
			i: INTEGER_32
		do
			from
				i := lower
			until
				i > upper
			loop
				if test.item ([item (i), i]) then
					action.call ([item (i), i])
				end
				i := i + 1
			end
		end

feature -- Duplication

	copy (other: like Current)
			-- Take the bounds and items of `other', in storage of its own.
		do
			if other /= Current then
				standard_copy (other)
				area := other.area.twin
			end
		end

feature {NONE} -- Implementation

	additional_space: INTEGER_32
			-- Extra room added when the storage grows.
		do
			Result := (area.capacity // 2).max (5)
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

	resize_to (new_lower, new_upper: INTEGER_32)
			-- Move the bounds to `new_lower' .. `new_upper', which include the current ones;
			-- new slots get the default value of G.
		require
			includes_current: new_lower <= lower and upper <= new_upper
		local
			new_area: SPECIAL [G]
			offset: INTEGER_32
		do
			offset := lower - new_lower
			create new_area.make_empty (new_upper - new_lower + 1)
			new_area.fill_with_default (0, offset - 1)
			new_area.copy_data (area, 0, offset, count)
			new_area.fill_with_default (offset + count, new_upper - new_lower)
			area := new_area
			lower := new_lower
			upper := new_upper
		end

invariant
	consistent_count: count = upper - lower + 1
	non_negative_count: count >= 0

end
