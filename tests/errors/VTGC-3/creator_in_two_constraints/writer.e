deferred class
	WRITER

feature {NONE} -- Initialization

	make
			-- Set up.
		deferred
		end

end
