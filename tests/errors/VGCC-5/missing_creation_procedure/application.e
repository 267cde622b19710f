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
			create p -- E: VGCC(5)
			create q.make (1, 2)
			print (q.x)
		end

end
