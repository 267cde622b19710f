note
	description: "A delivery van."

class
	VAN

create
	make,
	make_with_route

feature {NONE} -- Initialization

	make (a_count: INTEGER)
			-- Van with `a_count' stops to make.
		do
			stop_count := a_count
		end

	make_with_route (a_route: ROUTE)
			-- Van following `a_route'.
		do
			stop_count := a_route.length
		end

feature -- Access

	stop_count: INTEGER
			-- Stops still to make.

feature -- Element change

	follow (a_route: ROUTE)
			-- Follow `a_route'.
		do
			stop_count := a_route.length
		end

	set_stop_count (a_count: INTEGER)
			-- Make `a_count' stops.
		do
			stop_count := a_count
		end

end
