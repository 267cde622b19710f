note
	description: "Containers holding a finite number of items, counted by `count'."

deferred class
	FINITE [G]

inherit
	CONTAINER [G]

feature -- Measurement

	count: INTEGER_32
			-- Number of items.
		deferred
		ensure
			non_negative: Result >= 0
		end

feature -- Status report

	is_empty: BOOLEAN
			-- Is `count' zero?
		do
			Result := count = 0
		end

end
