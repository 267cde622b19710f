class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			p, q: POINT
		do
			create p
			create q
			print (p + q) -- E: VWOE
			if p < q then -- E: VWOE
				print ("smaller%N")
			end
			print (-p) -- E: VWOE
		end

end
