class
	HOLDER [G -> separate CELL]

create
	make

feature {NONE} -- Initialization

	make (x: G)
			-- Keep `x'; a call on the argument is controlled, one on the attribute is not.
		do
			item := x
			x.put (5)
			item.put (4) -- E: VUTA(3)
		end

feature -- Access

	item: G
			-- The cell kept.

end
