class
	GENERIC_SEPARATE_VALUES

create
	make

feature {NONE} -- Initialization

	make
			-- Relay integers through a separate cell.
		local
			l_cell: separate CELL [INTEGER]
			l_relay: RELAY [INTEGER]
		do
			create l_cell
			create l_relay
			l_relay.send (l_cell, 42)
			print (l_relay.last (l_cell))
		end

end
