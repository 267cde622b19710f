note
	description: "[
		Iteration cursors over linked lists; what `across' uses for a LINKED_LIST.
		They follow the cells from the first one and do not move the list's own cursor.
	]"

class
	LINKED_LIST_ITERATION_CURSOR [G]

inherit
	ITERATION_CURSOR [G]

	ITERABLE [G]

create
	make

feature {NONE} -- Initialization

	make (s: like target)
			-- Prepare an iteration over `s' (call `start' before use).
		do
			target := s
		ensure
			target_set: target = s
		end

feature -- Access

	target: LINKED_LIST [G]
			-- The list being iterated.

	item: G
			-- <Precursor>
		do
			check attached active as a then
				Result := a.item
			end
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
			Result := active = Void
		end

	is_first: BOOLEAN
			-- Is the cursor on the first element?
		do
			Result := cursor_index = 1 and not after
		end

	is_last: BOOLEAN
			-- Is the cursor on the last element?
		do
			Result := attached active as a and then a.right = Void
		end

feature -- Cursor movement

	start
			-- Go to the first element.
		do
			active := target.first_element
			cursor_index := 1
		end

	forth
			-- <Precursor>
		do
			if attached active as a then
				active := a.right
			end
			cursor_index := cursor_index + 1
		end

feature {NONE} -- Implementation

	active: detachable BI_LINKABLE [G]
			-- Cell of the current element.

end
