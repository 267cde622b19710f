note
	description: "[
		The most general data structures: they hold zero or more items of type G.
		Searches compare with `=' (references) unless `compare_objects' was called,
		after which they compare with `~' (object equality).
	]"

deferred class
	CONTAINER [G]

feature -- Access

	has (v: G): BOOLEAN
			-- Does the structure hold `v'?
			-- (Compared with `=' or `~' according to `object_comparison'.)
		deferred
		ensure
			not_found_in_empty: Result implies not is_empty
		end

feature -- Status report

	is_empty: BOOLEAN
			-- Does the structure hold no item?
		deferred
		end

	object_comparison: BOOLEAN
			-- Do searches compare items with `~' rather than `='?

	changeable_comparison_criterion: BOOLEAN
			-- May `object_comparison' be changed?
		do
			Result := True
		end

feature -- Status setting

	compare_objects
			-- Make searches compare items with `~'.
		require
			changeable_comparison_criterion: changeable_comparison_criterion
		do
			object_comparison := True
		ensure
			object_comparison: object_comparison
		end

	compare_references
			-- Make searches compare items with `='.
		require
			changeable_comparison_criterion: changeable_comparison_criterion
		do
			object_comparison := False
		ensure
			reference_comparison: not object_comparison
		end

feature -- Conversion

	linear_representation: LINEAR [G]
			-- The items as a linear structure.
		deferred
		end

end
