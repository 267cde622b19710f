class
	LINE

create
	make

feature {NONE} -- Initialization

	make (a_slope: INTEGER)
			-- A line through the origin with slope `a_slope'.
		do
			slope := a_slope
		end

feature -- Access

	slope: INTEGER
			-- Slope.

	value (x: INTEGER): INTEGER
			-- The line's value at `x' (no alias).
		do
			Result := slope * x
		end

end
