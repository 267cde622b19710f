class
	BIRD

feature -- Basic operations

	move
			-- Fly.
		do
			print ("flying%N")
		end

end
