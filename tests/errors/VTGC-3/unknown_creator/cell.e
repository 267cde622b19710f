class
	CELL

create
	make

feature {NONE} -- Initialization

	make
			-- An empty cell.
		do
		end

end
