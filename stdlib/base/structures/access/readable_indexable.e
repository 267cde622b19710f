note
	description: "Structures whose items are reached by integer indices from `lower' to `upper'."

deferred class
	READABLE_INDEXABLE [G]

inherit
	ITERABLE [G]

feature -- Access

	item alias "[]" (i: INTEGER_32): G
			-- Item at index `i'.
		require
			valid_index: valid_index (i)
		deferred
		end

	new_cursor: INDEXABLE_ITERATION_CURSOR [G]
			-- <Precursor>
		do
			create {READABLE_INDEXABLE_ITERATION_CURSOR [G]} Result.make (Current)
			Result.start
		end

feature -- Measurement

	lower: INTEGER_32
			-- Smallest index.
		deferred
		end

	upper: INTEGER_32
			-- Largest index.
		deferred
		end

	index_set: INTEGER_INTERVAL
			-- The interval `lower' .. `upper'.
		do
			create Result.make (lower, upper)
		end

feature -- Status report

	valid_index (i: INTEGER_32): BOOLEAN
			-- Is `i' an index of an item?
		deferred
		ensure
			only_within_bounds: Result implies (lower <= i and i <= upper)
		end

invariant
	consistent_boundaries: upper < lower implies upper = lower - 1

end
