note
	description: "Containers to which items may be added and from which they may be removed."

deferred class
	COLLECTION [G]

inherit
	FINITE [G]

feature -- Status report

	extendible: BOOLEAN
			-- May items be added?
		deferred
		end

	prunable: BOOLEAN
			-- May items be removed?
		deferred
		end

feature -- Element change

	extend (v: G)
			-- Add `v' to the structure.
		require
			extendible: extendible
		deferred
		end

	fill (other: CONTAINER [G])
			-- Add every item of `other', as long as the structure is `extendible'.
		require
			extendible: extendible
		local
			lin: LINEAR [G]
		do
			lin := other.linear_representation
			across lin as c until not extendible loop
				extend (c.item)
			end
		end

feature -- Removal

	prune (v: G)
			-- Remove one occurrence of `v', if any.
		require
			prunable: prunable
		deferred
		end

	prune_all (v: G)
			-- Remove every occurrence of `v'.
		require
			prunable: prunable
		do
			from
			until
				not has (v)
			loop
				prune (v)
			end
		end

	wipe_out
			-- Remove every item.
		require
			prunable: prunable
		deferred
		ensure
			wiped_out: is_empty
		end

end
