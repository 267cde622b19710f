class
	BIRD

inherit
	ANIMAL
		redefine
			fly -- E: VDRS(1)
		end

feature -- Basic operations

	fly
			-- Take off.
		do
			print ("flap flap%N")
		end

end
