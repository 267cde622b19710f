class
	POOL [G -> CELL create open end] -- E: VTGC(3)@25

feature -- Access

	count: INTEGER
			-- Number of resources.

end
