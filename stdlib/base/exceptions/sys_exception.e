note
	description: "Systematic exceptions, as older libraries named them."

deferred class
	SYS_EXCEPTION

inherit
	OBSOLETE_EXCEPTION

end
