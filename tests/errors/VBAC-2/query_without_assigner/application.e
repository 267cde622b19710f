class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			box: BOX
		do
			create box
			box.size := 3 -- E: VBAC(2)
			print (box.size)
		end

end
