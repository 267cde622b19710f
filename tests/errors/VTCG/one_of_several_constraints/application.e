class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use a shelf of strings.
		local
			l_shelf: SHELF [STRING] -- E: VTCG
		do
			create l_shelf
		end

end
