note
	description: "Exceptions kept for programs written against older versions of the library."

deferred class
	OBSOLETE_EXCEPTION

inherit
	EXCEPTION

end
