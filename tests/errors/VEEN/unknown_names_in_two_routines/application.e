class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			p: POINT
		do
			create p
			p.move (1, 2)
			print (p.x + p.y)
			print (distance)
			show (p)
		end

feature -- Access

	distance: INTEGER
			-- Distance travelled.
		do
			Result := lenght -- E: VEEN
		end

feature -- Output

	show (a_point: POINT)
			-- Print `a_point'.
		do
			print (a_point.x)
			print (a_point.colour) -- E: VEEN
			a_point.move (1, 2, 3) -- E: VUAR(1)
		end

end
