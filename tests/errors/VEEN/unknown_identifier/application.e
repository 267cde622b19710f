class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			total := totl + 1 -- E: VEEN
			print (total)
		end

feature -- Access

	total: INTEGER
			-- Sum so far.

end
