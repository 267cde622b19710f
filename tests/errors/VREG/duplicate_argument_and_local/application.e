class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			shift (1, 2)
			count_up
		end

feature -- Basic operations

	shift (dx: INTEGER; dx: INTEGER) -- E: VREG
			-- Shift twice.
		do
			print ("shifting%N")
		end

	count_up
			-- Count to three.
		local
			i, j: INTEGER
			i: INTEGER -- E: VREG
		do
			print ("counting%N")
		end

end
