class
	BOX [G]

create
	make

feature {NONE} -- Initialization

	make
			-- An empty box: `item' is left unset.
		do
			count := 0
		end -- E: VEVI@3

feature -- Access

	item: G
			-- An attribute of an unmarked formal type must be set (it may be a reference).

	count: INTEGER
			-- Number of items.

end
