deferred class
	APPLICATION -- E: VSRT

feature -- Initialization

	make
			-- Run.
		do
			print (count.out)
		end

	count: INTEGER
			-- How many.
		deferred
		end

end
