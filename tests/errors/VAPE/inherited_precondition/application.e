class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use a public valve.
		local
			v: PUBLIC_VALVE
		do
			create v
			v.open
		end

end
