class
	DOG

inherit
	ANIMAL

feature -- Basic operations

	speak -- E: VMFN
			-- Bark.
		do
			print ("Woof%N")
		end

end
