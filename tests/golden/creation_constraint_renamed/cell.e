class
	CELL

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER)
			-- A cell holding `n'.
		do
			value := n
		end

feature -- Access

	value: INTEGER
			-- The value held.

end
