deferred class
	FISH

inherit
	ANIMAL
		undefine
			fly -- E: VDUS(1)
		end

end
