note
	description: "[
		Two-way lists kept in increasing order: `extend' (and `put', `force') insert
		an item before the first item not smaller than it and leave the cursor on it.
	]"

class
	SORTED_TWO_WAY_LIST [G -> COMPARABLE]

inherit
	TWO_WAY_LIST [G]
		redefine
			extend
		end

create
	make,
	make_from_iterable

feature -- Access

	min: G
			-- Smallest item.
		require
			not_empty: not is_empty
		do
			Result := first
		end

	max: G
			-- Largest item.
		require
			not_empty: not is_empty
		do
			Result := last
		end

	median: G
			-- Item in the middle position.
		require
			not_empty: not is_empty
		do
			Result := i_th ((count + 1) // 2)
		end

feature -- Status report

	sorted: BOOLEAN
			-- Is every item no larger than the next one?
		local
			p: detachable BI_LINKABLE [G]
		do
			from
				Result := True
				p := first_element
			until
				not Result or p = Void
			loop
				if attached p as pp then
					if attached pp.right as r then
						Result := pp.item <= r.item
					end
					p := pp.right
				end
			end
		end

feature -- Cursor movement

	search_after (v: G)
			-- Move the cursor to the first item not smaller than `v', or `after'.
		do
			from
				start
			until
				after or else v <= item
			loop
				forth
			end
		ensure
			argument_less_than_item: (not after) implies (v <= item)
		end

feature -- Element change

	extend (v: G)
			-- Insert `v' at its place in the order; the cursor ends on it.
		do
			search_after (v)
			put_left (v)
			back
		end

	sort
			-- Put the items back in increasing order (after `replace' or `put_i_th' broke it).
		local
			items: ARRAYED_LIST [G]
		do
			create items.make (count)
			across Current as c loop
				items.extend (c.item)
			end
			wipe_out
			across items as c loop
				extend (c.item)
			end
		ensure
			sorted: sorted
		end

end
