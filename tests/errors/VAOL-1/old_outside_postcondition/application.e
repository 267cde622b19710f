class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			increment
			print (count)
		end

feature -- Access

	count: INTEGER
			-- Current count.

feature -- Element change

	increment
			-- Add one to `count'.
		require
			small: old count < 10 -- E: VAOL(1)
		do
			count := old count + 1 -- E: VAOL(1)
		ensure
			one_more: count = old count + 1
		end

end
