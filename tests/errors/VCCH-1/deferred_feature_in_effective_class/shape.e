class
	SHAPE -- E: VCCH(1)

feature -- Measurement

	area: INTEGER
			-- Surface covered.
		deferred
		end

end
