class
	RELAY [reference G]

feature -- Transfer

	send (a_cell: separate CELL [G]; a_value: G)
			-- Put `a_value' into `a_cell'.
		do
			a_cell.put (a_value) -- E: VUAR(3)
		end

end
