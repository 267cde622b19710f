class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use a shelf.
		local
			l_shelf: SHELF [WORD]
		do
			create l_shelf
			print (l_shelf.text (create {WORD}.make))
		end

end
