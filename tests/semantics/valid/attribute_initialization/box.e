class
	BOX [G]

create
	make

feature {NONE} -- Initialization

	make (a_item: G)
			-- A box holding `a_item'.
		do
			item := a_item
		end

feature -- Access

	item: G
			-- An attribute of a formal generic type: set by each creation procedure.

end
