note
	description: "Iteration cursors over tables: each position has an `item' and the `key' it is stored under."

deferred class
	TABLE_ITERATION_CURSOR [G, K]

inherit
	ITERATION_CURSOR [G]

feature -- Access

	key: K
			-- Key of the current element.
		require
			valid_position: not after
		deferred
		end

end
