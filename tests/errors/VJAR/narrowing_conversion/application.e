class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			small: INTEGER
			big: INTEGER_64
			ratio: REAL_64
		do
			small := 5
			big := small
			ratio := small
			big := big * 2
			small := big -- E: VJAR
			small := ratio -- E: VJAR
			print (small)
		end

end
