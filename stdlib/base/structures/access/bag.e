note
	description: "Collections in which an item may occur several times."

deferred class
	BAG [G]

inherit
	COLLECTION [G]

feature -- Measurement

	occurrences (v: G): INTEGER_32
			-- Number of times `v' occurs.
			-- (Compared with `=' or `~' according to `object_comparison'.)
		deferred
		ensure
			non_negative: Result >= 0
		end

end
