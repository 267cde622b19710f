class
	GENERIC_CONSTRAINTS

create
	make

feature {NONE} -- Initialization

	make
			-- Fill a shelf of words.
		local
			l_shelf: SHELF [WORD, WORD, INTEGER]
		do
			create l_shelf
			l_shelf.fill (create {WORD}.make)
			print (l_shelf.text)
			print (l_shelf.smaller (1, 2))
		end

end
