deferred class
	ROBOT

inherit
	MACHINE
		undefine
			serial, -- E: VDUS(2)
			voltage -- E: VDUS(2)
		end

end
