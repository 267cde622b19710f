class
	ANIMAL

feature -- Basic operations

	speak
			-- Make a sound.
		do
			print ("...%N")
		end

end
