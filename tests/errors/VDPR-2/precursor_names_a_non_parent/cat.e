class
	CAT

inherit
	ANIMAL
		redefine
			speak
		end

feature -- Basic operations

	speak
			-- Meow.
		do
			print ("Meow%N")
		end

end
