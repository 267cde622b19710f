note
	description: "[
		Containers where the structure, not the client, decides which item is
		accessible (`item') and removed next (`remove'): stacks and queues.
		They can also be traversed with `across', in the order of `linear_representation'.
	]"

deferred class
	DISPENSER [G]

inherit
	ACTIVE [G]
		redefine
			prune_all
		end

	ITERABLE [G]

feature -- Access

	new_cursor: ITERATION_CURSOR [G]
			-- A cursor over a snapshot of the items, in the order of `linear_representation'.
		do
			Result := linear_representation.new_cursor
		end

feature -- Status report

	readable: BOOLEAN
			-- Is there an item to read?
		do
			Result := not is_empty
		end

	writable: BOOLEAN
			-- Is there an item to modify?
		do
			Result := not is_empty
		end

	extendible: BOOLEAN
			-- May items be added? (Yes.)
		do
			Result := True
		end

feature -- Element change

	put (v: G)
			-- Add `v' (same as `extend').
		require
			extendible: extendible
		deferred
		end

	force (v: G)
			-- Add `v' (same as `extend').
		require
			extendible: extendible
		deferred
		end

	append (s: SEQUENCE [G])
			-- Add the items of `s', in order.
		do
			across s as c loop
				extend (c.item)
			end
		end

feature -- Removal

	prune (v: G)
			-- Do nothing: items are removed only with `remove'.
		do
		end

	prune_all (v: G)
			-- Do nothing: items are removed only with `remove'.
		do
		end

invariant
	readable_definition: readable = not is_empty
	writable_definition: writable = not is_empty

end
