deferred class
	READER

feature {NONE} -- Initialization

	make
			-- Set up.
		deferred
		end

end
