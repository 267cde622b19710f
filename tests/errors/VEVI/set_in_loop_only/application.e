class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			i: INTEGER
			last, both: STRING
		do
			from
				i := 0
			until
				i >= limit
			loop
				last := "item"
				i := i + 1
			end
			print (last.count) -- E: VEVI
			if limit > 0 then
				both := "some"
			else
				both := "none"
			end
			print (both.count)
		end

feature -- Access

	limit: INTEGER
			-- Number of rounds.

end
