class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Add a few numbers.
		do
			total := 3 + 4
			print (total)
			print ("%N")
		end

feature -- Access

	total: INTEGER
			-- Sum so far.

	average: like totl -- E: VTAT(1)
			-- Misspelt anchor.

	scale (factor: like ratio) -- E: VTAT(1)
			-- Scale by `factor'; there is no `ratio'.
		do
			print ("scaled%N")
		end

end
