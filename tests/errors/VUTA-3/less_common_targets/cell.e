class
	CELL

create
	make

feature {NONE} -- Initialization

	make
			-- Empty cell.
		do
		end

feature -- Access

	count: INTEGER
			-- Last value put.

	put (v: INTEGER)
			-- Keep `v'.
		do
			count := v
		end

end
