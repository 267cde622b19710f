class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Start counting.
		do
			count := 1
			print (count)
		end

feature -- Access

	count: INTEGER
			-- Current count.

invariant
	positive: Result > 0 -- E: VEEN(2)

end
