note
	description: "Plans a route and hands it to a delivery van."

class
	DELIVERY

create
	make

feature {NONE} -- Initialization

	make
			-- Plan a route with two stops and dispatch two vans.
		local
			l_route: ROUTE
			l_van: separate VAN
			l_spare: separate VAN
		do
			l_route.stops.extend (3)
			l_route.stops.extend (7)
			create l_van.make (l_route.length)
			create l_spare.make_with_route (l_route) -- E: VUAR(4)
			dispatch (l_van, l_route)
		end

feature -- Basic operations

	dispatch (a_van: separate VAN; a_route: ROUTE)
			-- Send `a_van' along `a_route'.
		do
			a_van.follow (a_route) -- E: VUAR(4)
			a_van.set_stop_count (a_route.length)
			show (a_route)
		end

	show (a_route: ROUTE)
			-- Print the number of stops of `a_route'.
		do
			print (a_route.length)
		end

end
