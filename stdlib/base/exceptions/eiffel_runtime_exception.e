note
	description: "Exceptions raised by the run time."

deferred class
	EIFFEL_RUNTIME_EXCEPTION

inherit
	LANGUAGE_EXCEPTION

end
