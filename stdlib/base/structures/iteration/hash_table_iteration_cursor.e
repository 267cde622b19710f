note
	description: "[
		Iteration cursors over hash tables, in the table's iteration order;
		what `across' uses for a HASH_TABLE. They do not move the table's own cursor.
	]"

class
	HASH_TABLE_ITERATION_CURSOR [G, K -> detachable HASHABLE]

inherit
	TABLE_ITERATION_CURSOR [G, K]

	ITERABLE [G]

create
	make

feature {NONE} -- Initialization

	make (t: like target)
			-- Prepare an iteration over `t' (call `start' before use).
		do
			target := t
			position := -1
		ensure
			target_set: target = t
		end

feature -- Access

	target: HASH_TABLE [G, K]
			-- The table being iterated.

	item: G
			-- <Precursor>
		do
			Result := target.content.item (position)
		end

	key: K
			-- <Precursor>
		do
			Result := target.keys.item (position)
		end

	cursor_index: INTEGER_32
			-- Position of the cursor in the iteration, counting from 1.

	new_cursor: like Current
			-- A copy of the current cursor, restarted.
		do
			Result := twin
			Result.start
		end

feature -- Status report

	after: BOOLEAN
			-- <Precursor>
		do
			Result := position < 0 or position >= target.keys.count
		end

	is_first: BOOLEAN
			-- Is the cursor on the first element?
		do
			Result := cursor_index = 1 and not after
		end

	is_last: BOOLEAN
			-- Is the cursor on the last element?
		do
			Result := not after and then target.next_iteration_position (position) >= target.keys.count
		end

feature -- Cursor movement

	start
			-- Go to the first element.
		do
			position := target.next_iteration_position (-1)
			cursor_index := 1
		end

	forth
			-- <Precursor>
		do
			position := target.next_iteration_position (position)
			cursor_index := cursor_index + 1
		end

feature {NONE} -- Implementation

	position: INTEGER_32
			-- Index of the current element in the table's storage.

end
