class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			b: BOOK
		do
			create b.make (100)
			print (b.pages)
		end

end
