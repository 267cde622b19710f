class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			reset
			print (count)
		end

feature -- Access

	count: INTEGER
			-- Current count.

feature -- Element change

	reset
			-- Set `count' to zero.
		do
			count := 0
			Result := count -- E: VEEN(2)
		end

end
