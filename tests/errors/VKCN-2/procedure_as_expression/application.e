class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			p: POINT
			n: INTEGER
		do
			create p
			n := reset -- E: VKCN(2)
			print (p.move (1, 1)) -- E: VKCN(2)
			print (n)
		end

feature -- Element change

	reset
			-- Nothing to reset.
		do
			print ("reset%N")
		end

end
