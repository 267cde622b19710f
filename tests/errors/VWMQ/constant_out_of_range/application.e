class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			small: INTEGER_8
		do
			small := {INTEGER_8} 100
			print (small)
			print ({INTEGER_8} 200) -- E: VWMQ
			print ({NATURAL_8} 256) -- E: VWMQ
		end

end
