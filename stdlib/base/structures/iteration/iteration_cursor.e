note
	description: "[
		External cursors used by `across' loops: `item' is the current element,
		`forth' moves to the next one and `after' tells when there is none left.
	]"

deferred class
	ITERATION_CURSOR [G]

feature -- Access

	item: G
			-- Element at the current position.
		require
			valid_position: not after
		deferred
		end

feature -- Status report

	after: BOOLEAN
			-- Has the iteration gone past the last element?
		deferred
		end

feature -- Cursor movement

	forth
			-- Move to the next element.
		require
			valid_position: not after
		deferred
		end

end
