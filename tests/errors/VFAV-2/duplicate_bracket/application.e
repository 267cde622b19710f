class
	APPLICATION

inherit
	TABLE

create
	make

feature {NONE} -- Initialization

	make
			-- Use the bracket.
		do
			print (Current [3].out + "%N")
		end

feature -- Access

	at alias "[]" (i: INTEGER): INTEGER -- E: VFAV(2)
			-- Three times `i'.
		do
			Result := 3 * i
		end

end
