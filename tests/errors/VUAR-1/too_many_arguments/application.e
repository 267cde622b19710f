class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			p: POINT
		do
			create p
			p.move (1, 2, 3) -- E: VUAR(1)
			print (p.x)
		end

end
