note
	description: "[
		Iteration cursors over arrayed lists; what `across' uses for an ARRAYED_LIST.
		They do not move the list's own cursor.
	]"

class
	ARRAYED_LIST_ITERATION_CURSOR [G]

inherit
	INDEXABLE_ITERATION_CURSOR [G]

create
	make

feature {NONE} -- Initialization

	make (s: like target)
			-- Prepare an iteration over `s' (call `start' before use).
		do
			target := s
			step := 1
		ensure
			target_set: target = s
			default_step: step = 1
		end

feature -- Access

	target: ARRAYED_LIST [G]
			-- The list being iterated.

feature {NONE} -- Target access

	target_lower: INTEGER_32
			-- <Precursor>
		do
			Result := 1
		end

	target_upper: INTEGER_32
			-- <Precursor>
		do
			Result := target.count
		end

	target_has_index (i: INTEGER_32): BOOLEAN
			-- <Precursor>
		do
			Result := target.valid_index (i)
		end

	target_item (i: INTEGER_32): G
			-- <Precursor>
		do
			Result := target.area.item (i - 1)
		end

end
