class
	CAGE [G -> ANIMAL]

feature -- Access

	occupant: detachable G
			-- The animal in the cage, if any.

feature -- Element change

	put (a_animal: G)
			-- Lock `a_animal' in.
		do
			occupant := a_animal
		end

end
