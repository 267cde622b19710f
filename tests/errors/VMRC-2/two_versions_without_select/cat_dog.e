class
	CAT_DOG -- E: VMRC(2)

inherit
	DOG
		rename
			speak as bark
		end

	CAT
		rename
			speak as meow
		end

end
