class
	COUNTER

create
	make,
	value, -- E: VGCP(2)
	reset_all -- E: VGCP(2)

feature {NONE} -- Initialization

	make
			-- Start at zero.
		do
		end

feature -- Access

	value: INTEGER
			-- Current count.

end
