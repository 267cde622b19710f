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
			box.value := 5
			print (box.value)
		end

end
