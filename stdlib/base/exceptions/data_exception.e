note
	description: "Exceptions about data: input and output, stored objects."

deferred class
	DATA_EXCEPTION

inherit
	EIFFEL_RUNTIME_EXCEPTION

end
