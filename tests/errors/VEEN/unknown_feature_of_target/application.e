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
			print (p.x)
			print (p.z) -- E: VEEN
		end

end
