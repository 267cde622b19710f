class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			i: INTEGER
		do
			from
				i := 3
			until
				i -- E: VWBE
			loop
				print (i)
				i := i - 1
			end
		end

end
