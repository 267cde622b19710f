class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			p: POINT
		do
			create p
			reset (3, p)
			print (size)
		end

feature -- Access

	size: INTEGER
			-- Size (a function, not an attribute).
		do
			Result := 10
		end

feature -- Element change

	reset (a_count: INTEGER; a_point: POINT)
			-- Try to change what cannot be changed.
		do
			a_count := 0 -- E: VJAW
			create a_point -- E: VJAW
			size := a_count -- E: VJAW
		end

end
