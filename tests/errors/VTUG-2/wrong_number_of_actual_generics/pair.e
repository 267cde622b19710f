class
	PAIR [G, H]

feature -- Access

	first: detachable G
			-- First item, if any.

	second: detachable H
			-- Second item, if any.

feature -- Element change

	set (a_first: G; a_second: H)
			-- Keep `a_first' and `a_second'.
		do
			first := a_first
			second := a_second
		end

end
