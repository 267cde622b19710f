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
			p.move ("one", 2) -- E: VUAR(2)
			print (p.y)
		end

end
