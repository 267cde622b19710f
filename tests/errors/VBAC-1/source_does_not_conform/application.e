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
			box.value := 10
			box.value := "ten" -- E: VBAC(1)
			print (box.value)
		end

end
