class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			b: BOX
			n: INTEGER
		do
			create b.make (5)
			n := b
			print (n)
		end

end
