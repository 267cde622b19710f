class
	HOLDER [reference G -> ANY, expanded H, frozen K]
		-- Formal generics marked `reference', `expanded' and `frozen'.

feature -- Access

	item: detachable G

	count: H

	key: detachable K

feature -- Change

	put (a_item: G)
			-- Keep `a_item'.
		do
			item := a_item
		end

end
