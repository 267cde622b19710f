class
	CYCLIC_CONSTRAINTS

create
	make

feature {NONE} -- Initialization

	make
			-- Use a pair of strings.
		local
			l_pair: PAIR [STRING, STRING]
		do
			create l_pair
			l_pair.put ("x")
		end

end
