deferred class
	SHAPE

feature -- Measurement

	area: REAL_64
			-- Surface.
		deferred
		end

end
