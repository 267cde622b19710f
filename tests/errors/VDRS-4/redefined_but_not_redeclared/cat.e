class
	CAT

inherit
	ANIMAL
		redefine
			speak -- E: VDRS(4)
		end

feature -- Basic operations

	purr
			-- Purr.
		do
			print ("Purr%N")
		end

end
