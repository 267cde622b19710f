class
	FRAGILE

feature -- Access

	value: INTEGER

	checked_value: INTEGER
		require
			positive: value > 0
		do
			Result := value
		end

feature -- Change

	explode
		require
			never_true: value < 0
		do
			value := -1
		end

	set (v: INTEGER)
		do
			value := v
		end

end
