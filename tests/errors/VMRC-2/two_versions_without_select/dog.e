class
	DOG

inherit
	ANIMAL
		redefine
			speak
		end

feature -- Basic operations

	speak
			-- Bark.
		do
			print ("Woof%N")
		end

end
