class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			s, t: SHAPE
		do
			create s -- E: VGCC(1)
			create {SHAPE} t -- E: VGCC(1)
			print ("no shapes%N")
		end

end
