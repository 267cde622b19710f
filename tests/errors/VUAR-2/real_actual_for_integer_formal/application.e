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
			n := 3
			scale (n)
			scale (2)
			repeat_times (2.5) -- E: VUAR(2)
		end

feature -- Basic operations

	scale (factor: REAL_64)
			-- Print `factor'.
		do
			print (factor)
		end

	repeat_times (count: INTEGER)
			-- Print `count'.
		do
			print (count)
		end

end
