note
	description: "[
		Sequences whose items are numbered from 1 to `count': reachable by index
		(`i_th', `first', `last'), with the internal cursor at position `index'
		(0 is `before', `count' + 1 is `after').
	]"

deferred class
	CHAIN [G]

inherit
	SEQUENCE [G]

feature -- Access

	first: G
			-- Item at position 1.
		require
			not_empty: not is_empty
		do
			Result := i_th (1)
		end

	last: G
			-- Item at position `count'.
		require
			not_empty: not is_empty
		do
			Result := i_th (count)
		end

	i_th alias "[]", at alias "@" (i: INTEGER_32): G assign put_i_th
			-- Item at position `i'.
		require
			valid_index: valid_index (i)
		deferred
		end

	cursor: CURSOR
			-- The current position of the internal cursor, for `go_to'.
		deferred
		end

feature -- Measurement

	lower: INTEGER_32 = 1
			-- Index of the first item.

feature -- Status report

	valid_index (i: INTEGER_32): BOOLEAN
			-- Is `i' the position of an item?
		do
			Result := 1 <= i and i <= count
		ensure
			definition: Result = (1 <= i and i <= count)
		end

	valid_cursor_index (i: INTEGER_32): BOOLEAN
			-- May the internal cursor be moved to position `i'?
		do
			Result := 0 <= i and i <= count + 1
		ensure
			definition: Result = (0 <= i and i <= count + 1)
		end

	valid_cursor (p: CURSOR): BOOLEAN
			-- May the internal cursor be moved to `p'?
		deferred
		end

	isfirst: BOOLEAN
			-- Is the internal cursor on the first item?
		do
			Result := not is_empty and index = 1
		ensure
			valid_position: Result implies not is_empty
		end

	islast: BOOLEAN
			-- Is the internal cursor on the last item?
		do
			Result := not is_empty and index = count
		ensure
			valid_position: Result implies not is_empty
		end

feature -- Cursor movement

	go_i_th (i: INTEGER_32)
			-- Move the internal cursor to position `i'.
		require
			valid_cursor_index: valid_cursor_index (i)
		deferred
		ensure
			position_expected: index = i
		end

	move (i: INTEGER_32)
			-- Move the internal cursor `i' positions; it stops `before' or `after'
			-- when `i' goes beyond the ends.
		do
			go_i_th ((index + i).max (0).min (count + 1))
		ensure
			too_far_right: (old index + i > count) implies exhausted
			too_far_left: (old index + i < 1) implies exhausted
			expected_index: (not exhausted) implies (index = old index + i)
		end

	go_to (p: CURSOR)
			-- Move the internal cursor back to the position `p' remembers.
		require
			valid_cursor: valid_cursor (p)
		deferred
		end

feature -- Element change

	put (v: G)
			-- Put `v' in place of the current item (same as `replace').
		require
			writable: writable
		do
			replace (v)
		ensure
			same_count: count = old count
		end

	put_i_th (v: G; i: INTEGER_32)
			-- Put `v' at position `i'.
		require
			valid_index: valid_index (i)
		deferred
		ensure
			inserted: i_th (i) = v
		end

feature -- Transformation

	swap (i: INTEGER_32)
			-- Exchange the current item with the item at position `i'.
		require
			not_off: not off
			valid_index: valid_index (i)
		local
			old_item: G
		do
			old_item := item
			replace (i_th (i))
			put_i_th (old_item, i)
		end

feature -- Duplication

	duplicate (n: INTEGER_32): like Current
			-- A new chain of the same type with the items from the cursor position on,
			-- `n' of them at most.
		require
			not_off_unless_after: off implies after
			valid_subchain: n >= 0
		deferred
		end

invariant
	non_negative_index: index >= 0
	index_small_enough: index <= count + 1
	off_definition: off = ((index = 0) or (index = count + 1))

end
