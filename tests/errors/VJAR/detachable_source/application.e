class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			name := "nobody"
			update
			print (name)
		end

feature -- Access

	name: STRING
			-- Current name.

	count: INTEGER
			-- Number of known names.

	found_name: detachable STRING
			-- A name, if one is known.
		do
			if count > 0 then
				Result := "Ann"
			end
		end

feature -- Element change

	update
			-- Replace `name'.
		do
			name := found_name -- E: VJAR
		end

end
