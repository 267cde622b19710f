class
	APPLICATION [G] -- E: VSRT

create
	make

feature {NONE} -- Initialization

	make
			-- Run.
		do
			print ("hello%N")
		end

end
