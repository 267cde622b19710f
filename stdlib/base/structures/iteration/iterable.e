note
	description: "Structures that an `across' loop can traverse with an external cursor."

deferred class
	ITERABLE [G]

feature -- Access

	new_cursor: ITERATION_CURSOR [G]
			-- A fresh cursor on the first item (`after' at once if there is none).
		deferred
		end

end
