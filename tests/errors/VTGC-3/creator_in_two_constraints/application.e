class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use a pool of devices.
		local
			p: POOL [DEVICE]
		do
			create p
			print (p.count)
		end

end
