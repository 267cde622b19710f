class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			n: INTEGER
			flag: BOOLEAN
		do
			n := "seven" -- E: VJAR
			flag := 1 -- E: VJAR
			print (n)
			print (flag)
		end

end
