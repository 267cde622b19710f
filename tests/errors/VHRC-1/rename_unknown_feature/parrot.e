class
	PARROT

inherit
	ANIMAL
		rename
			fly as soar -- E: VHRC(1)
		end

end
