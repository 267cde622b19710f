note
	description: "Exceptions signalled by the hardware."

deferred class
	HARDWARE_EXCEPTION

inherit
	MACHINE_EXCEPTION

end
