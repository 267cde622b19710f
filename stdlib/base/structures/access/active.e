note
	description: "Collections with a current item, which may be read, replaced or removed."

deferred class
	ACTIVE [G]

inherit
	BAG [G]

feature -- Access

	item: G
			-- The current item.
		require
			readable: readable
		deferred
		end

feature -- Status report

	readable: BOOLEAN
			-- Is there a current item to read?
		deferred
		end

	writable: BOOLEAN
			-- Is there a current item to modify?
		deferred
		end

feature -- Element change

	replace (v: G)
			-- Put `v' in place of the current item.
		require
			writable: writable
		deferred
		end

feature -- Removal

	remove
			-- Remove the current item.
		require
			prunable: prunable
			writable: writable
		deferred
		end

end
