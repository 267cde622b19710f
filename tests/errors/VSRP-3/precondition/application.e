class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make -- E: VSRP(3)
			-- Run when ready.
		require
			ready: is_ready
		do
			print ("go%N")
		end

	is_ready: BOOLEAN
			-- Ready to go?

end
