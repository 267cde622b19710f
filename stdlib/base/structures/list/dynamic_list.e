note
	description: "Lists to which items may be added and from which they may be removed anywhere."

deferred class
	DYNAMIC_LIST [G]

inherit
	LIST [G]
		redefine
			prune_all
		end

feature -- Status report

	extendible: BOOLEAN
			-- May items be added? (Yes.)
		do
			Result := True
		end

	prunable: BOOLEAN
			-- May items be removed? (Yes.)
		do
			Result := True
		end

feature -- Element change

	put_front (v: G)
			-- Add `v' at the beginning; the cursor stays where it is.
		require
			extendible: extendible
		deferred
		ensure
			one_more: count = old count + 1
			item_inserted: first = v
		end

	put_left (v: G)
			-- Add `v' to the left of the cursor; the cursor stays on its item.
		require
			extendible: extendible
			not_before: not before
		deferred
		ensure
			one_more: count = old count + 1
			new_index: index = old index + 1
		end

	put_right (v: G)
			-- Add `v' to the right of the cursor; the cursor stays where it is.
		require
			extendible: extendible
			not_after: not after
		deferred
		ensure
			one_more: count = old count + 1
			same_index: index = old index
		end

feature -- Removal

	remove_left
			-- Remove the item to the left of the cursor; the cursor stays on its item.
		require
			left_exists: index > 1
		deferred
		ensure
			one_less: count = old count - 1
			new_index: index = old index - 1
		end

	remove_right
			-- Remove the item to the right of the cursor; the cursor stays where it is.
		require
			right_exists: index < count
		deferred
		ensure
			one_less: count = old count - 1
			same_index: index = old index
		end

	prune (v: G)
			-- Remove the first occurrence of `v' at or after the cursor, if any;
			-- the cursor ends on the next item, or `after'.
		do
			search (v)
			if not exhausted then
				remove
			end
		end

	prune_all (v: G)
			-- Remove every occurrence of `v'; the cursor ends `after'.
		do
			from
				start
				search (v)
			until
				exhausted
			loop
				remove
				search (v)
			end
		ensure then
			is_exhausted: exhausted
		end

end
