note
	description: "[
		Sets of comparable items kept in increasing order in a two-way list: `extend'
		(and `put', `force', `fill', ...) add an item only if the set does not hold it yet
		(compared with `=', or `~' after `compare_objects'), and iteration goes from the
		smallest item to the largest. The list features stay available, as in EiffelBase.
	]"

class
	TWO_WAY_SORTED_SET [G -> COMPARABLE]

inherit
	SORTED_TWO_WAY_LIST [G]
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
			-- Add `v' at its place in the order unless the set holds it already;
			-- the cursor ends on the item equal to `v'.
		local
			found: BOOLEAN
		do
			from
				search_after (v)
			until
				found or after or else v < item
			loop
				if same_item (item, v) then
					found := True
				else
					forth
				end
			end
			if not found then
				put_left (v)
				back
			end
		ensure then
			in_set: has (v)
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

	symdif (other: CONTAINER [G])
			-- Remove the items that are also in `other' and add those of `other' that were not in the set.
		local
			l_other: ARRAYED_LIST [G]
		do
			create l_other.make (0)
			across other.linear_representation as c loop
				l_other.extend (c.item)
			end
			across l_other as c loop
				if has (c.item) then
					prune (c.item)
				else
					extend (c.item)
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
