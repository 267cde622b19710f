class
	CELL

feature -- Access

	count: INTEGER
			-- Data kept so far.

	keep (d: DATA)
			-- Count `d'.
		do
			count := count + 1
		end

end
