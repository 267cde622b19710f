note
	description: "A counter cell."

class
	CELL

feature -- Access

	count: INTEGER
			-- Last value put.

	put (v: INTEGER)
			-- Keep `v'.
		do
			count := v
		end

end
