note
	description: "[
		Contiguous blocks of `capacity' slots of which the first `count' are in use,
		indexed from 0: the storage under arrays, lists, queues and hash tables.
		Items are added with `extend' (or `force' at index `count'); slots beyond
		`count' cannot be read.
	]"
	implementation: "[
		The storage itself and the operations that move many items at once are
		`external "Python"' (bound by class and feature name). Their bodies must know
		the default value of T (0, 0.0, False, the null character, or Void for
		references) for `fill_with_default'. Everything else is Eiffel.
	]"

frozen class
	SPECIAL [T]

inherit
	READABLE_INDEXABLE [T]
		redefine
			copy,
			is_equal
		end

create
	make_empty,
	make_filled

feature {NONE} -- Initialization

	make_empty (n: INTEGER_32)
			-- Make room for `n' items; none is in use yet.
		require
			non_negative_argument: n >= 0
		external
			"Python"
		ensure
			capacity_set: capacity = n
			count_set: count = 0
		end

	make_filled (v: T; n: INTEGER_32)
			-- Make room for `n' items, all in use and equal to `v'.
		require
			non_negative_argument: n >= 0
		do
			make_empty (n)
			fill_with (v, 0, n - 1)
		ensure
			capacity_set: capacity = n
			count_set: count = n
		end

feature -- Access

	item alias "[]" (i: INTEGER_32): T assign put
			-- Item at index `i' (indices start at 0).
		require
			valid_index: valid_index (i)
		external
			"Python"
		end

	at alias "@" (i: INTEGER_32): T
			-- Item at index `i'.
		require
			valid_index: valid_index (i)
		do
			Result := item (i)
		end

	index_of (v: T; start_position: INTEGER_32): INTEGER_32
			-- Index of the first item equal (`~') to `v' from `start_position' on, or -1.
		require
			valid_start_position: start_position >= 0
		do
			from
				Result := start_position
			until
				Result >= count or else item (Result) ~ v
			loop
				Result := Result + 1
			end
			if Result >= count then
				Result := -1
			end
		ensure
			found_or_not_found: Result = -1 or else (Result >= 0 and then Result < count)
		end

	to_array: ARRAY [T]
			-- An array, indexed from 1, sharing this storage.
		do
			create Result.make_from_special (Current)
		ensure
			lower_set: Result.lower = 1
			upper_set: Result.upper = count
		end

feature -- Measurement

	lower: INTEGER_32 = 0
			-- Smallest index.

	upper: INTEGER_32
			-- Largest index in use.
		do
			Result := count - 1
		end

	count: INTEGER_32
			-- Number of slots in use.
		external
			"Python"
		end

	capacity: INTEGER_32
			-- Number of slots available.
		external
			"Python"
		end

feature -- Status report

	valid_index (i: INTEGER_32): BOOLEAN
			-- Is `i' the index of a slot in use?
		do
			Result := 0 <= i and i < count
		end

	filled_with (v: T; start_index, end_index: INTEGER_32): BOOLEAN
			-- Are all items from `start_index' to `end_index' equal (`=') to `v'?
		require
			start_index_non_negative: start_index >= 0
			start_index_not_too_big: start_index <= end_index + 1
			end_index_valid: end_index < count
		local
			i: INTEGER_32
		do
			from
				Result := True
				i := start_index
			until
				i > end_index or not Result
			loop
				Result := item (i) = v
				i := i + 1
			end
		end

	same_items (other: like Current; source_index, destination_index, n: INTEGER_32): BOOLEAN
			-- Are the `n' items of `other' from `source_index' equal (`=') to
			-- the `n' items of the current block from `destination_index'?
		require
			source_index_non_negative: source_index >= 0
			destination_index_non_negative: destination_index >= 0
			n_non_negative: n >= 0
			n_is_small_enough_for_source: source_index + n <= other.count
			n_is_small_enough_for_destination: destination_index + n <= count
		local
			i: INTEGER_32
		do
			from
				Result := True
			until
				i >= n or not Result
			loop
				Result := other.item (source_index + i) = item (destination_index + i)
				i := i + 1
			end
		ensure
			valid_on_empty_area: n = 0 implies Result
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Are the items in use those of `other', compared with `='?
		do
			Result := count = other.count and then same_items (other, 0, 0, count)
		end

feature -- Element change

	put (v: T; i: INTEGER_32)
			-- Replace the item at index `i' by `v'.
		require
			index_large_enough: i >= 0
			index_small_enough: i < count
		external
			"Python"
		ensure
			same_count: count = old count
		end

	force (v: T; i: INTEGER_32)
			-- Replace the item at index `i' by `v', or add `v' when `i' is `count'.
		require
			index_large_enough: i >= 0
			index_small_enough: i <= count
			not_full: i = count implies count < capacity
		do
			if i < count then
				put (v, i)
			else
				extend (v)
			end
		ensure
			count_updated: count = (i + 1).max (old count)
		end

	extend (v: T)
			-- Add `v' at index `count'.
		require
			count_small_enough: count < capacity
		external
			"Python"
		ensure
			count_increased: count = old count + 1
		end

	fill_with (v: T; start_index, end_index: INTEGER_32)
			-- Put `v' at every index from `start_index' to `end_index', using slots
			-- beyond `count' if needed.
		require
			start_index_non_negative: start_index >= 0
			start_index_in_bound: start_index <= count
			start_index_not_too_big: start_index <= end_index + 1
			end_index_valid: end_index < capacity
		external
			"Python"
		ensure
			count_definition: count = (old count).max (end_index + 1)
		end

	fill_with_default (start_index, end_index: INTEGER_32)
			-- Put the default value of T at every index from `start_index' to `end_index',
			-- using slots beyond `count' if needed.
		require
			start_index_non_negative: start_index >= 0
			start_index_in_bound: start_index <= count
			start_index_not_too_big: start_index <= end_index + 1
			end_index_valid: end_index < capacity
		external
			"Python"
		ensure
			count_definition: count = (old count).max (end_index + 1)
		end

	copy_data (other: SPECIAL [T]; source_index, destination_index, n: INTEGER_32)
			-- Copy the `n' items of `other' from `source_index' to the current block
			-- from `destination_index' on.
		require
			source_index_non_negative: source_index >= 0
			destination_index_non_negative: destination_index >= 0
			destination_index_in_bound: destination_index <= count
			n_non_negative: n >= 0
			n_is_small_enough_for_source: source_index + n <= other.count
			n_is_small_enough_for_destination: destination_index + n <= capacity
		external
			"Python"
		ensure
			count_updated: count = (old count).max (destination_index + n)
		end

	move_data (source_index, destination_index, n: INTEGER_32)
			-- Move `n' items from `source_index' to `destination_index' (the ranges may overlap).
		require
			source_index_non_negative: source_index >= 0
			destination_index_non_negative: destination_index >= 0
			destination_index_in_bound: destination_index <= count
			n_non_negative: n >= 0
			n_is_small_enough_for_source: source_index + n <= count
			n_is_small_enough_for_destination: destination_index + n <= capacity
		external
			"Python"
		ensure
			count_updated: count = (old count).max (destination_index + n)
		end

feature -- Resizing

	keep_head (n: INTEGER_32)
			-- Keep only the first `n' items.
		require
			non_negative_argument: n >= 0
			less_than_count: n <= count
		external
			"Python"
		ensure
			count_updated: count = n
		end

	keep_tail (n: INTEGER_32)
			-- Keep only the last `n' items, moved to the front.
		require
			non_negative_argument: n >= 0
			less_than_count: n <= count
		external
			"Python"
		ensure
			count_updated: count = n
		end

	remove_head (n: INTEGER_32)
			-- Remove the first `n' items; the others move to the front.
		require
			non_negative_argument: n >= 0
			less_than_count: n <= count
		do
			keep_tail (count - n)
		ensure
			count_updated: count = old count - n
		end

	remove_tail (n: INTEGER_32)
			-- Remove the last `n' items.
		require
			non_negative_argument: n >= 0
			less_than_count: n <= count
		do
			keep_head (count - n)
		ensure
			count_updated: count = old count - n
		end

	resized_area (n: INTEGER_32): like Current
			-- A new block with capacity `n' holding the first items (at most `n') of this one.
		require
			valid_new_count: n >= 0
		external
			"Python"
		ensure
			new_capacity: Result.capacity = n
			new_count: Result.count = count.min (n)
		end

	aliased_resized_area (n: INTEGER_32): like Current
			-- This block or a new one, with capacity `n' and the first items (at most `n')
			-- of this one; use the result in place of this block from then on.
		require
			valid_new_count: n >= 0
		external
			"Python"
		ensure
			new_capacity: Result.capacity = n
			new_count: Result.count = count.min (n)
		end

	resized_area_with_default (v: T; n: INTEGER_32): like Current
			-- A new block of `n' items: those of this one, then `v' up to index `n' - 1.
		require
			valid_new_count: n >= 0
		do
			Result := resized_area (n)
			Result.fill_with (v, Result.count, n - 1)
		ensure
			new_count: Result.count = n
		end

	aliased_resized_area_with_default (v: T; n: INTEGER_32): like Current
			-- Like `aliased_resized_area', then `v' up to index `n' - 1.
		require
			valid_new_count: n >= 0
		do
			Result := aliased_resized_area (n)
			Result.fill_with (v, Result.count, n - 1)
		ensure
			new_count: Result.count = n
		end

feature -- Removal

	wipe_out
			-- Put no slot in use.
		external
			"Python"
		ensure
			empty: count = 0
		end

feature -- Duplication

	copy (other: like Current)
			-- Take the capacity and items of `other', in storage of its own.
		external
			"Python"
		end

feature -- Iteration

	do_all_in_bounds (action: PROCEDURE [TUPLE [T]]; start_index, end_index: INTEGER_32)
			-- Apply `action' to the items from `start_index' to `end_index'.
		require
			start_index_non_negative: start_index >= 0
			end_index_valid: end_index < count
		local
			i: INTEGER_32
		do
			from
				i := start_index
			until
				i > end_index
			loop
				action.call ([item (i)])
				i := i + 1
			end
		end

	there_exists_in_bounds (test: FUNCTION [TUPLE [T], BOOLEAN]; start_index, end_index: INTEGER_32): BOOLEAN
			-- Does `test' hold for an item from `start_index' to `end_index'?
		require
			start_index_non_negative: start_index >= 0
			end_index_valid: end_index < count
		local
			i: INTEGER_32
		do
			from
				i := start_index
			until
				i > end_index or Result
			loop
				Result := test.item ([item (i)])
				i := i + 1
			end
		end

	for_all_in_bounds (test: FUNCTION [TUPLE [T], BOOLEAN]; start_index, end_index: INTEGER_32): BOOLEAN
			-- Does `test' hold for every item from `start_index' to `end_index'?
		require
			start_index_non_negative: start_index >= 0
			end_index_valid: end_index < count
		local
			i: INTEGER_32
		do
			from
				Result := True
				i := start_index
			until
				i > end_index or not Result
			loop
				Result := test.item ([item (i)])
				i := i + 1
			end
		end

invariant
	count_within_capacity: 0 <= count and count <= capacity

end
