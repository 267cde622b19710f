note
	description: "Iteration cursors over any READABLE_INDEXABLE structure (arrays, tuples, intervals, ...)."

class
	READABLE_INDEXABLE_ITERATION_CURSOR [G]

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

	target: READABLE_INDEXABLE [G]
			-- The structure being iterated.

feature {NONE} -- Target access

	target_lower: INTEGER_32
			-- <Precursor>
		do
			Result := target.lower
		end

	target_upper: INTEGER_32
			-- <Precursor>
		do
			Result := target.upper
		end

	target_has_index (i: INTEGER_32): BOOLEAN
			-- <Precursor>
		do
			Result := target.valid_index (i)
		end

	target_item (i: INTEGER_32): G
			-- <Precursor>
		do
			Result := target.item (i)
		end

end
