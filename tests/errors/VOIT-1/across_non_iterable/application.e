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
			across p as c loop -- E: VOIT(1)
				print ("coordinate%N")
			end
			across 10 as c loop -- E: VOIT(1)
				print ("tick%N")
			end
		end

end
