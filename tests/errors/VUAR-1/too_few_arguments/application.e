class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			c: CANVAS
		do
			greet -- E: VUAR(1)
			create c.make (3) -- E: VUAR(1)
			print (c.width)
		end

feature -- Output

	greet (a_name: STRING)
			-- Greet `a_name'.
		do
			print ("Hello, " + a_name + "%N")
		end

end
