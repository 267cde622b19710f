class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Show the name before setting it.
		do
			show
			name := "scoop"
		end

	show
			-- Print `name'.
		do
			print (name) -- E: VEVI@11
		end

feature -- Access

	name: STRING
			-- Set last.

end
