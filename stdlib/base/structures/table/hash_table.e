note
	description: "[
		Tables of items of type G stored under keys of type K, found by hashing.
		`put' inserts only if the key is absent, `force' inserts or replaces,
		`extend' inserts a key known to be absent, `replace' changes an existing item;
		the status queries (`inserted', `found', `conflict', ...) tell what the last
		operation did. Items are iterated (with `across', or with `start', `forth',
		`item_for_iteration' and `key_for_iteration') in insertion order, except that
		a new item may take the place of a removed one.
	]"
	implementation: "[
		Written in Eiffel over SPECIALs, with the same layout and algorithms as EiffelBase
		so that iteration orders and capacities match EiffelStudio's: items and keys are
		stored in insertion order in `content' and `keys' (a removed entry leaves a hole
		marked in `deleted_marks'); `indexes_map' is an open-addressing table with double
		hashing (`capacity' is a prime) from hash positions to those indices. The default
		key (Void, or 0, False, ... for expanded keys) is not hashed: its index is kept at
		position `capacity' of `indexes_map'.
	]"

class
	HASH_TABLE [G, K -> detachable HASHABLE]

inherit
	FINITE [G]
		rename
			has as has_item
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
	make_equal

feature -- Initialization

	make (n: INTEGER_32)
			-- Make an empty table with room for `n' items (it grows as needed).
		require
			n_non_negative: n >= 0
		local
			size: INTEGER_32
			l_default: detachable G
		do
			size := n.max (minimum_capacity)
			size := size + size // 2 + 1
			capacity := higher_prime (size)
			create content.make_empty (n + 1)
			create keys.make_empty (n + 1)
			create deleted_marks.make_filled (False, n + 1)
			create indexes_map.make_filled (impossible_position, capacity + 1)
			iteration_position := n + 1
			count := 0
			deleted_item_position := impossible_position
			control := 0
			found_item := l_default
			has_default := False
			item_position := 0
			lowest_deleted_position := max_position
		ensure
			breathing_space: n < capacity
			more_than_minimum: capacity > minimum_capacity
		end

	make_equal (n: INTEGER_32)
			-- Make an empty table with room for `n' items, comparing items with `~'.
		require
			n_non_negative: n >= 0
		do
			make (n)
			compare_objects
		ensure
			compare_objects: object_comparison
		end

	accommodate (n: INTEGER_32)
			-- Make room for `n' items, keeping every item.
		require
			n_non_negative: n >= 0
		local
			i, nb: INTEGER_32
			new_table: like Current
		do
			from
				new_table := empty_duplicate (keys.count.max (n))
				nb := keys.count
			until
				i = nb
			loop
				if occupied (i) then
					new_table.put (content.item (i), keys.item (i))
				end
				i := i + 1
			end
			if has_default then
				i := indexes_map.item (capacity)
				new_table.put (content.item (i), keys.item (i))
			end
			content := new_table.content
			keys := new_table.keys
			deleted_marks := new_table.deleted_marks
			indexes_map := new_table.indexes_map
			capacity := new_table.capacity
			iteration_position := new_table.iteration_position
		ensure
			count_not_changed: count = old count
		end

feature -- Access

	found_item: detachable G
			-- Item found by the last search, or the previous item after `force' and `put'.

	item alias "[]", at alias "@" (key: K): detachable G assign force
			-- Item stored under `key', if any (otherwise the default value of G).
		local
			l_item_position, l_deleted_item_position, l_control: INTEGER_32
		do
			l_item_position := item_position
			l_deleted_item_position := deleted_item_position
			l_control := control
			internal_search (key)
			if found then
				Result := content.item (position)
			end
			item_position := l_item_position
			deleted_item_position := l_deleted_item_position
			control := l_control
		end

	has (key: K): BOOLEAN
			-- Is there an item stored under `key'?
		local
			l_item_position, l_deleted_item_position, l_control: INTEGER_32
		do
			l_item_position := item_position
			l_deleted_item_position := deleted_item_position
			l_control := control
			internal_search (key)
			Result := found
			item_position := l_item_position
			deleted_item_position := l_deleted_item_position
			control := l_control
		end

	has_key (key: K): BOOLEAN
			-- Is there an item stored under `key'? Set `found' and `found_item'.
		local
			l_item_position: INTEGER_32
			l_default: detachable G
		do
			l_item_position := item_position
			internal_search (key)
			Result := found
			if Result then
				found_item := content.item (position)
			else
				found_item := l_default
			end
			item_position := l_item_position
		ensure
			found: Result = found
		end

	has_item (v: G): BOOLEAN
			-- Is `v' one of the items?
			-- (Compared with `=' or `~' according to `object_comparison'.)
		local
			i, nb: INTEGER_32
		do
			if has_default then
				Result := v = content.item (indexes_map.item (capacity))
			end
			from
				nb := content.count
			until
				i = nb or Result
			loop
				Result := occupied (i) and then same_item (v, content.item (i))
				i := i + 1
			end
		end

	current_keys: ARRAY [K]
			-- The keys, in iteration order, indexed from 1.
		local
			j, old_iteration_position: INTEGER_32
		do
			if is_empty then
				create Result.make_empty
			else
				old_iteration_position := iteration_position
				from
					start
					create Result.make_filled (key_for_iteration, 1, count)
					j := 1
					forth
				until
					off
				loop
					j := j + 1
					Result.put (key_for_iteration, j)
					forth
				end
				iteration_position := old_iteration_position
			end
		ensure
			good_count: Result.count = count
		end

	item_for_iteration: G
			-- Item at the iteration position.
		require
			not_off: not off
		do
			Result := content.item (iteration_position)
		end

	key_for_iteration: K
			-- Key at the iteration position.
		require
			not_off: not off
		do
			Result := keys.item (iteration_position)
		end

	new_cursor: HASH_TABLE_ITERATION_CURSOR [G, K]
			-- <Precursor>
		do
			create Result.make (Current)
			Result.start
		end

	hash_code_of (a_key: K): INTEGER_32
			-- Hash code of `a_key' (0 for Void).
		do
			if attached a_key as k then
				Result := k.hash_code
			end
		ensure
			non_negative: Result >= 0
		end

feature -- Measurement

	count: INTEGER_32
			-- Number of items.

	capacity: INTEGER_32
			-- Number of positions of the hash table proper.

	occurrences (v: G): INTEGER_32
			-- Number of items equal to `v'.
			-- (Compared with `=' or `~' according to `object_comparison'.)
		local
			old_iteration_position: INTEGER_32
		do
			old_iteration_position := iteration_position
			from
				start
			until
				off
			loop
				if same_item (item_for_iteration, v) then
					Result := Result + 1
				end
				forth
			end
			iteration_position := old_iteration_position
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the current table and `other' hold the same items under the same keys?
		do
			if count = other.count and then object_comparison = other.object_comparison and then has_default = other.has_default then
				Result := True
				across Current as c until not Result loop
					other.search (c.key)
					if other.found then
						if object_comparison then
							Result := c.item ~ other.found_item
						else
							Result := c.item = other.found_item
						end
					else
						Result := False
					end
				end
			end
		end

	same_keys (a_search_key, a_key: K): BOOLEAN
			-- Are `a_search_key' and `a_key' the same key? (By default: `~'.)
		do
			Result := a_search_key ~ a_key
		end

	disjoint (other: HASH_TABLE [G, K]): BOOLEAN
			-- Do the current table and `other' have no key in common?
		do
			Result := is_empty or else other.is_empty or else not across other as o some has (o.key) end
		end

feature -- Status report

	full: BOOLEAN = False
			-- Is there no room for more items? (Never: the table grows.)

	extendible: BOOLEAN = True
			-- May items be added? (Yes.)

	prunable: BOOLEAN = True
			-- May items be removed? (Yes.)

	conflict: BOOLEAN
			-- Did the last operation find the key already present and leave it alone?
		do
			Result := control = conflict_constant
		end

	inserted: BOOLEAN
			-- Did the last operation insert an item?
		do
			Result := control = inserted_constant
		end

	replaced: BOOLEAN
			-- Did the last operation replace an item?
		do
			Result := control = replaced_constant
		end

	removed: BOOLEAN
			-- Did the last operation remove an item?
		do
			Result := control = removed_constant
		end

	found: BOOLEAN
			-- Did the last operation find the key it looked for?
		do
			Result := control = found_constant
		end

	not_found: BOOLEAN
			-- Did the last operation not find the key it looked for?
		do
			Result := control = not_found_constant
		end

	after, off: BOOLEAN
			-- Is the iteration position past the last item?
		do
			Result := is_off_position (iteration_position)
		end

feature -- Cursor movement

	start
			-- Move the iteration position to the first item.
		do
			iteration_position := next_iteration_position (-1)
		end

	forth
			-- Move the iteration position to the next item, or `off'.
		require
			not_off: not off
		do
			iteration_position := next_iteration_position (iteration_position)
		end

	search (key: K)
			-- Look for `key'; set `found' or `not_found', and `found_item'.
		local
			l_item_position: INTEGER_32
			l_default: detachable G
		do
			l_item_position := item_position
			internal_search (key)
			if found then
				found_item := content.item (position)
			else
				found_item := l_default
			end
			item_position := l_item_position
		ensure
			found_or_not_found: found or not_found
		end

feature -- Element change

	put (new: G; key: K)
			-- Store `new' under `key' if there is no item under it (then `inserted');
			-- otherwise leave the table alone (then `conflict'). `found_item' is the item
			-- now stored under `key'.
		local
			l_default_key: detachable K
			new_position, new_index_position: INTEGER_32
		do
			internal_search (key)
			if found then
				control := conflict_constant
				found_item := content.item (position)
			else
				if soon_full then
					add_space
					internal_search (key)
				end
				if deleted_item_position = impossible_position then
					new_position := keys.count
					new_index_position := item_position
				else
					new_position := deleted_position (deleted_item_position)
					new_index_position := deleted_item_position
					deleted_marks.force (False, new_position)
				end
				indexes_map.put (new_position, new_index_position)
				content.force (new, new_position)
				keys.force (key, new_position)
				if key = l_default_key then
					has_default := True
				end
				count := count + 1
				found_item := new
				control := inserted_constant
			end
		ensure
			conflict_or_inserted: conflict or inserted
			now_present: has (key)
			one_more_if_inserted: inserted implies (count = old count + 1)
			unchanged_if_conflict: conflict implies (count = old count)
		end

	force (new: G; key: K)
			-- Store `new' under `key', replacing any item stored under it; `found' tells
			-- whether there was one, and `found_item' is that item.
		local
			l_default_key: detachable K
			l_default: detachable G
			new_position, new_index_position: INTEGER_32
		do
			internal_search (key)
			if not_found then
				if soon_full then
					add_space
					internal_search (key)
				end
				if deleted_item_position = impossible_position then
					new_position := keys.count
					new_index_position := item_position
				else
					new_position := deleted_position (deleted_item_position)
					new_index_position := deleted_item_position
					deleted_marks.force (False, new_position)
				end
				indexes_map.put (new_position, new_index_position)
				keys.force (key, new_position)
				if key = l_default_key then
					has_default := True
				end
				count := count + 1
				found_item := l_default
			else
				new_position := position
				found_item := content.item (new_position)
			end
			content.force (new, new_position)
		ensure
			now_present: has (key)
			found_or_not_found: found or not_found
			same_count_or_one_more: (count = old count) or (count = old count + 1)
		end

	extend (new: G; key: K)
			-- Store `new' under `key', which must be absent.
		require
			not_present: not has (key)
		local
			l_default_key: detachable K
			new_position, new_index_position: INTEGER_32
		do
			internal_search (key)
			if soon_full then
				add_space
				internal_search (key)
			end
			if deleted_item_position = impossible_position then
				new_position := keys.count
				new_index_position := item_position
			else
				new_position := deleted_position (deleted_item_position)
				new_index_position := deleted_item_position
				deleted_marks.force (False, new_position)
			end
			indexes_map.put (new_position, new_index_position)
			content.force (new, new_position)
			keys.force (key, new_position)
			if key = l_default_key then
				has_default := True
			end
			count := count + 1
			control := inserted_constant
		ensure
			inserted: inserted
			one_more: count = old count + 1
		end

	replace (new: G; key: K)
			-- Put `new' in place of the item stored under `key', if any (then `replaced',
			-- otherwise `not_found'); `found_item' is the previous item.
		local
			l_default: detachable G
		do
			internal_search (key)
			if found then
				found_item := content.item (position)
				content.put (new, position)
				control := replaced_constant
			else
				found_item := l_default
			end
		ensure
			replaced_or_not_found: replaced or not_found
		end

	replace_key (new_key: K; old_key: K)
			-- Move the item stored under `old_key' to `new_key', if `new_key' is free
			-- (then `replaced'; `conflict' if it is not, `not_found' if `old_key' is absent).
		local
			l_item: G
		do
			internal_search (new_key)
			if not found then
				internal_search (old_key)
				if found then
					l_item := content.item (position)
					remove (old_key)
					put (l_item, new_key)
					control := replaced_constant
				end
			else
				control := conflict_constant
				found_item := content.item (position)
			end
		ensure
			same_count: count = old count
			replaced_or_conflict_or_not_found: replaced or conflict or not_found
		end

	merge (other: HASH_TABLE [G, K])
			-- Store every item of `other' under its key, replacing the items already there.
		do
			across other as c loop
				force (c.item, c.key)
			end
		end

feature -- Removal

	remove (key: K)
			-- Remove the item stored under `key', if any (then `removed', otherwise `not_found').
		local
			l_default_key: detachable K
			l_default: detachable G
			pos, nb: INTEGER_32
		do
			internal_search (key)
			if found then
				pos := position
				if key = l_default_key then
					has_default := False
				end
				deleted_marks.put (True, pos)
				indexes_map.put (-pos + deleted_mark, item_position)
				if iteration_position = pos then
					forth
				end
				count := count - 1
				lowest_deleted_position := pos.min (lowest_deleted_position)
				if lowest_deleted_position = count then
					nb := content.count - lowest_deleted_position
					content.remove_tail (nb)
					keys.remove_tail (nb)
					deleted_marks.fill_with (False, lowest_deleted_position, deleted_marks.count - 1)
					lowest_deleted_position := max_position
				end
				control := removed_constant
				found_item := l_default
			end
		ensure
			removed_or_not_found: removed or not_found
			not_present: not has (key)
			one_less: removed implies (count = old count - 1)
		end

	prune (v: G)
			-- Remove the first item equal to `v' at or after the iteration position.
		do
			from
			until
				after or else same_item (item_for_iteration, v)
			loop
				forth
			end
			if not after then
				remove (key_for_iteration)
			end
		end

	wipe_out
			-- Remove every item.
		local
			l_default: detachable G
		do
			content.wipe_out
			keys.wipe_out
			deleted_marks.fill_with (False, 0, deleted_marks.count - 1)
			indexes_map.fill_with (impossible_position, 0, capacity)
			found_item := l_default
			count := 0
			item_position := 0
			iteration_position := keys.count
			control := 0
			has_default := False
		ensure
			wiped_out: is_empty
		end

feature -- Conversion

	linear_representation: ARRAYED_LIST [G]
			-- The items, in iteration order.
		local
			old_iteration_position: INTEGER_32
		do
			old_iteration_position := iteration_position
			from
				create Result.make (count)
				start
			until
				off
			loop
				Result.extend (item_for_iteration)
				forth
			end
			iteration_position := old_iteration_position
		ensure
			good_count: Result.count = count
		end

feature -- Duplication

	copy (other: like Current)
			-- Take the items and keys of `other', in storage of its own.
		do
			if other /= Current then
				standard_copy (other)
				content := other.content.twin
				keys := other.keys.twin
				deleted_marks := other.deleted_marks.twin
				indexes_map := other.indexes_map.twin
			end
		end

feature {HASH_TABLE, HASH_TABLE_ITERATION_CURSOR} -- Implementation

	content: SPECIAL [G]
			-- The items, in insertion order (with holes where items were removed).

	keys: SPECIAL [K]
			-- The keys, at the same indices as their items.

	next_iteration_position (a_position: INTEGER_32): INTEGER_32
			-- The first index after `a_position' that holds an item (`keys.count' if none).
		require
			a_position_big_enough: a_position >= -1
		do
			from
				Result := a_position + 1
			until
				Result >= content.count or else not deleted_marks.item (Result)
			loop
				Result := Result + 1
			end
		end

feature {HASH_TABLE} -- Implementation

	indexes_map: SPECIAL [INTEGER_32]
			-- For each hash position, the index of its item in `content', or
			-- `impossible_position' (never used), or -index + `deleted_mark' (removed).

	deleted_marks: SPECIAL [BOOLEAN]
			-- Which indices of `content' hold a removed item.

	has_default: BOOLEAN
			-- Is there an item under the default key?

	iteration_position: INTEGER_32
			-- Index in `content' of the item at the iteration position.

	item_position: INTEGER_32
			-- Hash position set by `internal_search'.

	deleted_item_position: INTEGER_32
			-- First hash position of a removed item met by `internal_search', if any.

	control: INTEGER_32
			-- Outcome of the last operation.

	position: INTEGER_32
			-- Index in `content' of the item found by `internal_search'.
		do
			Result := indexes_map.item (item_position)
		end

feature {NONE} -- Implementation

	lowest_deleted_position: INTEGER_32
			-- Smallest index of a removed item since the storage was last trimmed.

	minimum_capacity: INTEGER_32 = 2
			-- Smallest number of items a table is made for.

	max_position: INTEGER_32 = 2147483645
			-- Larger than any index.

	impossible_position: INTEGER_32 = -1
			-- Mark of a hash position never used.

	deleted_mark: INTEGER_32 = -2
			-- Base of the marks of removed items in `indexes_map'.

	conflict_constant: INTEGER_32 = 1
	found_constant: INTEGER_32 = 2
	inserted_constant: INTEGER_32 = 4
	not_found_constant: INTEGER_32 = 8
	removed_constant: INTEGER_32 = 16
	replaced_constant: INTEGER_32 = 32
			-- Values of `control'.

	soon_full: BOOLEAN
			-- Is the storage full?
		do
			Result := keys.count = keys.capacity
		end

	add_space
			-- Grow the table by half.
		do
			accommodate (count + count // 2)
		end

	empty_duplicate (n: INTEGER_32): like Current
			-- An empty table like the current one with room for `n' items.
		require
			n_non_negative: n >= 0
		do
			create Result.make (n)
			if object_comparison then
				Result.compare_objects
			end
		end

	occupied (i: INTEGER_32): BOOLEAN
			-- Does index `i' hold an item with a key other than the default one?
		do
			if has_default then
				Result := i /= indexes_map.item (capacity) and then not deleted_marks.item (i)
			else
				Result := not deleted_marks.item (i)
			end
		end

	is_off_position (pos: INTEGER_32): BOOLEAN
			-- Is `pos' outside the indices holding items?
		do
			Result := pos < 0 or pos >= keys.count
		end

	deleted_position (a_pos: INTEGER_32): INTEGER_32
			-- Index in `content' of the removed item whose mark is at hash position `a_pos'
			-- (at most `keys.count').
		do
			Result := (-indexes_map.item (a_pos) + deleted_mark).min (keys.count)
		end

	internal_search (key: K)
			-- Look for `key': set `found' or `not_found', `item_position' (the hash
			-- position of `key', or where to insert it) and `deleted_item_position'.
		local
			l_default_key: detachable K
			hash_value, increment, l_pos, l_item_pos, stop: INTEGER_32
			first_deleted_position: INTEGER_32
		do
			first_deleted_position := impossible_position
			if key = l_default_key or key = Void then
				item_position := capacity
				if has_default then
					control := found_constant
				else
					control := not_found_constant
				end
			else
				from
					stop := capacity
					hash_value := hash_code_of (key)
					increment := 1 + hash_value \\ (capacity - 1)
					l_item_pos := (hash_value \\ capacity) - increment
					control := not_found_constant
				until
					stop = 0
				loop
					l_item_pos := (l_item_pos + increment) \\ capacity
					l_pos := indexes_map.item (l_item_pos)
					if l_pos >= 0 then
						if same_keys (keys.item (l_pos), key) then
							stop := 1
							control := found_constant
						end
					elseif l_pos = impossible_position then
						stop := 1
					elseif first_deleted_position = impossible_position then
						if not deleted_marks.item (-l_pos + deleted_mark) then
							stop := 1
						else
							first_deleted_position := l_item_pos
						end
					end
					stop := stop - 1
				end
				item_position := l_item_pos
			end
			deleted_item_position := first_deleted_position
		end

	same_item (a, b: detachable G): BOOLEAN
			-- Are `a' and `b' the same item for searches?
		do
			if object_comparison then
				Result := a ~ b
			else
				Result := a = b
			end
		end

	higher_prime (n: INTEGER_32): INTEGER_32
			-- Smallest prime number not below `n'.
		do
			if n <= 2 then
				Result := 2
			else
				from
					if n \\ 2 = 0 then
						Result := n + 1
					else
						Result := n
					end
				until
					is_prime (Result)
				loop
					Result := Result + 2
				end
			end
		end

	is_prime (n: INTEGER_32): BOOLEAN
			-- Is `n' a prime number?
		local
			divisor: INTEGER_32
		do
			if n = 2 then
				Result := True
			elseif n > 2 and n \\ 2 /= 0 then
				from
					divisor := 3
				until
					n \\ divisor = 0 or divisor * divisor > n
				loop
					divisor := divisor + 2
				end
				Result := divisor * divisor > n
			end
		end

invariant
	count_non_negative: count >= 0
	keys_enough_capacity: keys.count <= capacity + 1

end
