class
	TABLE

feature -- Access

	item alias "[]" (i: INTEGER): INTEGER
			-- Twice `i'.
		do
			Result := 2 * i
		end

end
