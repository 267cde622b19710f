class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use the bracket.
		do
			print (Current [3].out + "%N")
		end

feature -- Access

	item alias "[]" convert (i: INTEGER): INTEGER -- E: VFAV(5)
			-- Twice `i'.
		do
			Result := 2 * i
		end

end
