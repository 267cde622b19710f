class
	CELL

feature -- Access

	count: INTEGER
			-- Values kept so far.

	keep (p: PAIR)
			-- Count `p'.
		do
			count := count + 1
		end

end
