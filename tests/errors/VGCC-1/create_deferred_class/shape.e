deferred class
	SHAPE

feature -- Measurement

	area: INTEGER
			-- Surface covered.
		deferred
		end

end
