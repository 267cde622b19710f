class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			b: BOX [INTEGER]
		do
			create b.make
			print (b.item)
		end

end
