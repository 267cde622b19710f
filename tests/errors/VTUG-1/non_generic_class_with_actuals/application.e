class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Create a point.
		local
			p: POINT
		do
			create p
			p.move (1, 2)
			print (p.x)
			print ("%N")
		end

feature -- Access

	origin: detachable POINT [INTEGER] -- E: VTUG(1)
			-- POINT is not generic.

end
