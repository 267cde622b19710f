class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			print (name)
		end

feature -- Access

	count: INTEGER
			-- Number of items.

	name: STRING
			-- A word for `count'.
		do
			if count > 0 then
				Result := "many"
			end
		end -- E: VEVI@3

end
