class
	ORDERED_PAIR [G -> COMPARABLE]

create
	make

feature {NONE} -- Initialization

	make (a, b: G)
		do
			if a <= b then
				low := a
				high := b
			else
				low := b
				high := a
			end
		end

feature -- Access

	low, high: G

	contains (v: G): BOOLEAN
		do
			Result := low <= v and v <= high
		end

end
