note
	description: "Exceptions signalled by the operating system."

deferred class
	OPERATING_SYSTEM_EXCEPTION

inherit
	MACHINE_EXCEPTION

end
