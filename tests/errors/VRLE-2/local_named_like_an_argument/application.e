class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			show (3)
		end

feature -- Output

	show (n: INTEGER)
			-- Print a line.
		local
			n: INTEGER -- E: VRLE(2)
		do
			print ("showing%N")
		end

end
