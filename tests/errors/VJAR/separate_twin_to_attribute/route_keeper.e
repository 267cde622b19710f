note
	description: "Keeps copies of a route planned on another processor."

class
	ROUTE_KEEPER

create
	make

feature {NONE} -- Initialization

	make
			-- Plan a route on its own processor and keep copies of it.
		local
			l_route: separate ROUTE
		do
			create l_route.make
			keep (l_route)
		end

feature -- Basic operations

	keep (a_route: separate ROUTE)
			-- Keep copies of `a_route'.
		do
			copy_here := a_route.twin -- E: VJAR
			copy_here := a_route.deep_twin -- E: VJAR
			copy_there := a_route.twin
			copy_there := a_route.deep_twin
			print (a_route.waypoints.count.out + "%N")
		end

feature -- Access

	copy_here: detachable ROUTE
			-- A copy meant for this processor.

	copy_there: detachable separate ROUTE
			-- A copy on the route's processor.

end
