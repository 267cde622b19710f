class
	REGISTER

create
	make

feature {NONE} -- Initialization

	make
			-- A register holding 0.
		do
		end

feature -- Access

	value alias "[]": INTEGER -- E: VFAV(2)
			-- The value.
		do
			Result := stored
		end

	stored: INTEGER
			-- Stored value.

end
