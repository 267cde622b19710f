class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Relay strings through a separate cell.
		local
			l_cell: separate CELL [STRING]
			l_relay: RELAY [STRING]
		do
			create l_cell
			create l_relay
			l_relay.send (l_cell, "text")
		end

end
