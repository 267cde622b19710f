class
	FISH

feature -- Basic operations

	move
			-- Swim.
		do
			print ("swimming%N")
		end

end
