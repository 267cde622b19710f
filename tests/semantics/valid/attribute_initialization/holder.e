deferred class
	HOLDER [G]

feature -- Access

	value: G
			-- Of a formal type: must be set where G may be a reference type.

end
