class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			n: INTEGER
		do
			n := "three" -- E: VJAR
			if n then -- E: VWBE
				print ("non-zero%N")
			end
		end

end
