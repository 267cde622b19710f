deferred class
	ROBOT

inherit
	MACHINE
		undefine
			brand -- E: VDUS(2)
		end

end
