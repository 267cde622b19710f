class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use a pool of cells.
		local
			p: POOL [CELL]
		do
			create p
			print (p.count)
		end

end
