class
	ROBOT

feature -- Basic operations

	speak
			-- Beep after the parent's sound.
		do
			Precursor -- E: VDPR(1)
			print ("Beep%N")
		end

end
