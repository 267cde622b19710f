class
	NODE

inherit
	NODE -- E: VHPR(1)

feature -- Access

	value: INTEGER
			-- Stored value.

end
