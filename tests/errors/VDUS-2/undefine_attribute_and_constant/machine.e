class
	MACHINE

feature -- Access

	serial: INTEGER
			-- Serial number (an attribute).

	voltage: INTEGER = 230
			-- Supply voltage (a constant).

	frozen brand: STRING
			-- Maker's name (frozen: no descendant may change it).
		do
			Result := "ACME"
		end

	describe
			-- Print a description.
		do
			print (brand + "%N")
		end

end
