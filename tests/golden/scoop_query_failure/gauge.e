class
	GAUGE

feature -- Access

	level: INTEGER

	checked_level (limit: INTEGER): INTEGER
			-- `level', which must not exceed `limit'.
		require
			within_limit: level <= limit
		do
			Result := level
		end

feature -- Change

	set (v: INTEGER)
		do
			level := v
		end

end
