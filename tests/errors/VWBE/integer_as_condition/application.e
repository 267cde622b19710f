class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			count := 2
			check_count (count)
		end

feature -- Access

	count: INTEGER
			-- Number of items.

feature -- Basic operations

	check_count (n: INTEGER)
			-- Say whether there are items.
		require
			some_items: n -- E: VWBE
		do
			if count then -- E: VWBE
				print ("some items%N")
			end
		end

end
