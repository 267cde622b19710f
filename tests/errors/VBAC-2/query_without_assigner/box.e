class
	BOX

feature -- Access

	value: INTEGER assign set_value
			-- Content (with an assigner).

	size: INTEGER
			-- Capacity (no assigner).

	item alias "[]" (i: INTEGER): INTEGER
			-- Content multiplied by `i' (no assigner).
		do
			Result := value * i
		end

feature -- Element change

	set_value (v: INTEGER)
			-- Set `value' to `v'.
		do
			value := v
		end

end
