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
			print (b.to_ancestor = b)
		end

end
