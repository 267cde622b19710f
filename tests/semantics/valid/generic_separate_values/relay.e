class
	RELAY [G]
		-- Passes values of an unmarked formal generic to and from a separate CELL [G]:
		-- EiffelStudio accepts both (warning FORMAL-TRAITOR here).

feature -- Transfer

	send (a_cell: separate CELL [G]; a_value: G)
			-- Put `a_value' into `a_cell'.
		do
			a_cell.put (a_value)
		end

	last (a_cell: separate CELL [G]): detachable G
			-- The value in `a_cell'.
		do
			Result := a_cell.item
		end

end
