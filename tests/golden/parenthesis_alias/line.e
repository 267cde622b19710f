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

	value alias "()" (x: INTEGER): INTEGER
			-- The line's value at `x'.
		do
			Result := slope * x
		end

end
