class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			s: SNAKE
		do
			create s
			print ("a snake%N")
		end

end
