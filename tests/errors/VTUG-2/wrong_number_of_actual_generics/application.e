class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Build a pair.
		local
			p: PAIR [INTEGER, STRING]
		do
			create p
			p.set (1, "one")
			print ("pair built%N")
		end

feature -- Access

	names: detachable PAIR [STRING] -- E: VTUG(2)
			-- One actual generic instead of two.

	triple: detachable PAIR [INTEGER, INTEGER, INTEGER] -- E: VTUG(2)
			-- Three actual generics instead of two.

end
