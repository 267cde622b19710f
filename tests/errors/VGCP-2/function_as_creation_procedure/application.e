class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Make a counter.
		local
			c: COUNTER
		do
			create c.make
			print (c.value.out + "%N")
		end

end
