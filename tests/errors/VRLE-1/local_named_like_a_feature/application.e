class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			show
		end

feature -- Access

	count: INTEGER
			-- Number of items.

feature -- Output

	show
			-- Print the items.
		local
			count: INTEGER -- E: VRLE(1)
		do
			print ("showing%N")
		end

end
