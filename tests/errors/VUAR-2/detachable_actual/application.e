class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			greet ("Ann")
		end

feature -- Output

	greet (a_name: detachable STRING)
			-- Greet `a_name', which may be void.
		do
			show (a_name) -- E: VUAR(2)
		end

	show (s: STRING)
			-- Print `s'.
		do
			print (s + "%N")
		end

end
