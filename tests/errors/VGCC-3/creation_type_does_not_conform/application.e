class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			pet: ANIMAL
		do
			create {DOG} pet
			pet.speak
			create {ROCK} pet -- E: VGCC(3)
		end

end
