note
	description: "Exceptions coming from the machine: hardware and operating system errors."

deferred class
	MACHINE_EXCEPTION

inherit
	EXCEPTION

end
