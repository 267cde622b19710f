class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			name := "nobody"
			show
		end

feature -- Access

	name: STRING
			-- Current name.

	found_name: detachable STRING
			-- A name, if one is known.
		do
			Result := "Ann"
		end

feature -- Output

	show
			-- Print the found name.
		local
			s: STRING
		do
			if attached found_name as name then -- E: VUOT(1)
				print ("found%N")
			end
			s := "x"
			if attached found_name as s then -- E: VUOT(1)
				print ("found again%N")
			end
		end

end
