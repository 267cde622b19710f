class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			greeting: STRING
		do
			print (greeting.count) -- E: VEVI
			label_count (1)
		end

feature -- Output

	label_count (n: INTEGER)
			-- Print a word for `n'.
		local
			label: STRING
		do
			if n > 0 then
				label := "positive"
			end
			print (label.count) -- E: VEVI
		end

end
