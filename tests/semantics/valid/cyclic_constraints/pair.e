class
	PAIR [G -> H, H -> G]
		-- Each formal is constrained by the other: both conform to each other and to ANY.

feature -- Access

	first: detachable G

	second: detachable H

feature -- Change

	put (a_second: H)
			-- Store `a_second' as both items.
		local
			l_any: detachable ANY
		do
			first := a_second
			l_any := first
			second := first
			if attached first as l_first then
				print (l_first.out)
			end
		end

end
