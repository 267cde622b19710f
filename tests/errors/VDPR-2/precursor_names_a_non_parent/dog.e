class
	DOG

inherit
	ANIMAL
		redefine
			speak
		end

feature -- Basic operations

	speak
			-- Make the parent's sound, then bark.
		do
			Precursor {CAT} -- E: VDPR(2)
			print ("Woof%N")
		end

end
