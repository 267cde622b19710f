class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			add (5)
			print (total)
		end

feature -- Access

	total: INTEGER
			-- Sum so far.

feature -- Element change

	add (total: INTEGER) -- E: VRFA
			-- Add a value (the argument hides the attribute).
		do
			print ("adding%N")
		end

end
