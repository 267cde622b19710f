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
			count -- E: VKCN(1)
			p.x -- E: VKCN(1)
			print (count)
		end

feature -- Access

	count: INTEGER
			-- Number of points.

end
