class
	BOX

feature -- Access

	value: INTEGER assign set_value
			-- Content (a valid assigner).

	size: INTEGER assign set_size -- E: VFAC(1)
			-- Capacity (its assigner does not exist).

	count: INTEGER assign value -- E: VFAC(1)
			-- Items (its assigner is a query).

feature -- Element change

	set_value (v: INTEGER)
			-- Set `value' to `v'.
		do
			value := v
		end

end
