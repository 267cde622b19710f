class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			sum: INTEGER
		do
			across << 1, 2, 3 >> as total loop -- E: VOIT(2)
				print ("item%N")
			end
			sum := 0
			across << 4, 5 >> as sum loop -- E: VOIT(2)
				print ("item%N")
			end
			print (sum)
		end

feature -- Access

	total: INTEGER
			-- Sum so far.

end
