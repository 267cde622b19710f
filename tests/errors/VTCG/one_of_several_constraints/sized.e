deferred class
	SIZED

feature {NONE} -- Initialization

	make
			-- Initialise.
		deferred
		end

feature -- Access

	size: INTEGER
			-- Number of parts.
		deferred
		end

end
