class
	BUFFER

feature -- Access

	count: INTEGER
			-- Items put so far.

feature -- Element change

	put
			-- Add an item.
		do
			count := count + 1
		end

end
