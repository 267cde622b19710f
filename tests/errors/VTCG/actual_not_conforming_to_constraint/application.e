class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Fill the cages.
		local
			kennel: CAGE [DOG]
			d: DOG
		do
			create kennel
			create d
			kennel.put (d)
			print ("kennel ready%N")
		end

feature -- Access

	rock_cage: detachable CAGE [ROCK] -- E: VTCG
			-- A rock is not an animal.

end
