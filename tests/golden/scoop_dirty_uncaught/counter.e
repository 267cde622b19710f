class
	COUNTER

feature -- Access

	count: INTEGER

	next: INTEGER
			-- One more than the last time (a query with an effect, to show whether it ran).
		do
			count := count + 1
			Result := count
		end

feature -- Change

	set (v: INTEGER)
		do
			count := v
		end

	explode
		require
			never_true: count < 0
		do
		end

end
