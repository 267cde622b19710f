note
	description: "[
		Sets stored as arrayed lists: `extend' (and `put', `force') add an item only
		if it is not there yet. Membership uses `=' unless `compare_objects' was called.
	]"

class
	ARRAYED_SET [G]

inherit
	ARRAYED_LIST [G]
		rename
			put as list_put
		export
			{NONE} list_put
		redefine
			extend,
			prune
		end

create
	make,
	make_from_iterable

feature -- Element change

	extend, put (v: G)
			-- Add `v' unless it is already in the set.
		do
			if is_empty or else not has (v) then
				append_item (v)
			end
		end

	merge (other: CONTAINER [G])
			-- Add every item of `other' that is not in the set yet.
		do
			across other.linear_representation as c loop
				extend (c.item)
			end
		end

feature -- Removal

	prune (v: G)
			-- Remove `v' if it is in the set.
		do
			start
			Precursor (v)
		end

	intersect (other: CONTAINER [G])
			-- Keep only the items that are also in `other'.
		do
			from
				start
			until
				after
			loop
				if other.has (item) then
					forth
				else
					remove
				end
			end
		end

	subtract (other: CONTAINER [G])
			-- Remove the items that are also in `other'.
		do
			from
				start
			until
				after
			loop
				if other.has (item) then
					remove
				else
					forth
				end
			end
		end

feature -- Comparison

	is_subset (other: CONTAINER [G]): BOOLEAN
			-- Is every item of the set in `other'?
		do
			Result := across Current as c all other.has (c.item) end
		end

	is_superset (other: CONTAINER [G]): BOOLEAN
			-- Is every item of `other' in the set?
		do
			Result := across other.linear_representation as c all has (c.item) end
		end

	disjoint (other: CONTAINER [G]): BOOLEAN
			-- Do the set and `other' have no item in common?
		do
			Result := across Current as c all not other.has (c.item) end
		end

end
