note
	description: "Objects that give a short text for debuggers and traces."

deferred class
	DEBUG_OUTPUT

feature -- Status report

	debug_output: READABLE_STRING_GENERAL
			-- Text describing the current object.
		deferred
		end

end
