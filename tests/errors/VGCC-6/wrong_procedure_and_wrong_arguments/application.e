class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			p, q: POINT
		do
			create p.move (1, 2) -- E: VGCC(6)
			create q.make (1) -- E: VUAR(1)
			print ("done%N")
		end

end
