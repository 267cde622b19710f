deferred class
	TILE

feature -- Measurement

	area: INTEGER
			-- Number of unit squares.
		deferred
		end

end
