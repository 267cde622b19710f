class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			b: BOX
		do
			b := 5
			print (b.value)
		end

end
