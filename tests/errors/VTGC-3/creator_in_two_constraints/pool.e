class
	POOL [G -> {READER, WRITER} create make end] -- E: VTGC(3)@37

feature -- Access

	count: INTEGER
			-- Number of resources.

end
