class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Describe a square.
		do
			print (side * side)
			print ("%N")
		end

feature -- Access

	side: INTEGER
			-- Length of a side.

	paint (a_brush: BRUSH) -- E: VTCT
			-- Paint with `a_brush' (there is no class BRUSH).
		do
			print ("painting%N")
		end

	describe
			-- Print a description.
		local
			c: COLOUR -- E: VTCT
		do
			print ("a square%N")
		end

end
