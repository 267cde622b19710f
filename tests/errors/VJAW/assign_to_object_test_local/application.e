class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			if attached found_name as l_name then
				l_name := "Bob" -- E: VJAW
				print (l_name)
			end
		end

feature -- Access

	found_name: detachable STRING
			-- A name, if one is known.
		do
			Result := "Ann"
		end

end
