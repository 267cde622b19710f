class
	PARROT

inherit
	ANIMAL
		select
			fly -- E: VMSS(1)
		end

end
