class
	CELL [G]
		-- A value kept on its own processor.

feature -- Access

	item: detachable G

feature -- Change

	put (a_item: G)
			-- Keep `a_item'.
		do
			item := a_item
		end

end
