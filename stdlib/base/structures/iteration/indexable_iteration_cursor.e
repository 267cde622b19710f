note
	description: "[
		Iteration cursors over structures whose elements are reached by integer
		indices between a lower and an upper bound. They can walk backwards
		(`reversed') and skip elements (`with_step').
		Descendants say how to reach the target through `target_lower',
		`target_upper', `target_has_index' and `target_item'.
	]"

deferred class
	INDEXABLE_ITERATION_CURSOR [G]

inherit
	ITERATION_CURSOR [G]

	ITERABLE [G]

feature -- Access

	item: G
			-- Element of the target at `target_index'.
		do
			Result := target_item (target_index)
		end

	cursor_index: INTEGER_32
			-- Position of the cursor in the iteration, counting from 1.
		do
			Result := ((target_index - first_index).abs + step - 1) // step + 1
		ensure
			non_negative: Result >= 0
		end

	target_index: INTEGER_32
			-- Index in the target of the current element.

	first_index: INTEGER_32
			-- Index in the target where the iteration starts.

	last_index: INTEGER_32
			-- Index in the target where the iteration ends
			-- (below `first_index' when `is_reversed').

	step: INTEGER_32
			-- Distance between two successive elements of the iteration.

	new_cursor: like Current
			-- A copy of the current cursor, restarted.
		do
			Result := twin
			Result.start
		end

	reversed alias "-": like Current
			-- A copy of the current cursor that walks the other way.
		do
			Result := twin
			Result.reverse
		ensure
			flipped: Result.is_reversed = not is_reversed
		end

	with_step (n: INTEGER_32): like Current
			-- A copy of the current cursor moving `n' elements at a time.
		require
			n_positive: n > 0
		do
			Result := twin
			Result.set_step (n)
		ensure
			step_set: Result.step = n
		end

	incremented alias "+" (n: INTEGER_32): like Current
			-- A copy of the current cursor with a step larger by `n'.
		require
			valid_step: step + n > 0
		do
			Result := twin
			Result.set_step (step + n)
		end

	decremented alias "-" (n: INTEGER_32): like Current
			-- A copy of the current cursor with a step smaller by `n'.
		require
			valid_step: step > n
		do
			Result := twin
			Result.set_step (step - n)
		end

feature -- Status report

	after: BOOLEAN
			-- Is `target_index' outside the target's bounds?
		do
			Result := not target_has_index (target_index)
		end

	is_valid: BOOLEAN
			-- May the cursor still be used on its target?
		do
			Result := True
		end

	is_first: BOOLEAN
			-- Is the cursor on the first element of the iteration?
		do
			Result := target_index = first_index and not after
		end

	is_last: BOOLEAN
			-- Is the cursor on the last element of the iteration?
		do
			Result := target_index = last_index and not after
		end

	is_reversed: BOOLEAN
			-- Does the iteration go from the upper bound to the lower one?

feature -- Status setting

	reverse
			-- Swap the direction of the iteration.
		do
			is_reversed := not is_reversed
		ensure
			flipped: is_reversed = not old is_reversed
		end

	set_step (n: INTEGER_32)
			-- Move `n' elements at a time.
		require
			n_positive: n > 0
		do
			step := n
		ensure
			step_set: step = n
		end

feature -- Cursor movement

	start
			-- Go to the first element of the iteration.
		do
			if is_reversed then
				first_index := target_upper
				last_index := target_lower
			else
				first_index := target_lower
				last_index := target_upper
			end
			target_index := first_index
		end

	forth
			-- Go to the next element of the iteration.
		do
			if is_reversed then
				target_index := target_index - step
			else
				target_index := target_index + step
			end
		end

feature {NONE} -- Target access

	target_lower: INTEGER_32
			-- Lowest valid index of the target.
		deferred
		end

	target_upper: INTEGER_32
			-- Highest valid index of the target.
		deferred
		end

	target_has_index (i: INTEGER_32): BOOLEAN
			-- Is `i' a valid index of the target?
		deferred
		end

	target_item (i: INTEGER_32): G
			-- Element of the target at index `i'.
		require
			valid_index: target_has_index (i)
		deferred
		end

invariant
	step_positive: step > 0

end
