class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use a pair of strings.
		local
			l_pair: PAIR [STRING, INTEGER] -- E: VTCG
		do
			create l_pair
			l_pair.put (1)
		end

end
