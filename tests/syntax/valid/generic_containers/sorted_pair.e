note
	description: "Two comparable values kept in order: a constrained generic class."

class
	SORTED_PAIR [G -> COMPARABLE]

create
	make

feature {NONE} -- Initialization

	make (a, b: G)
			-- Store `a' and `b' in order.
		do
			if a <= b then
				low := a
				high := b
			else
				low := b
				high := a
			end
		ensure
			ordered: low <= high
		end

feature -- Access

	low, high: G
			-- The smaller and the larger value.

	contains (x: G): BOOLEAN
			-- Is `x' between `low' and `high'?
		do
			Result := low <= x and x <= high
		end

invariant
	ordered: low <= high

end
