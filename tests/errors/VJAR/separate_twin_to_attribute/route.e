note
	description: "A route of waypoints a robot follows."

class
	ROUTE

create
	make

feature {NONE} -- Initialization

	make
			-- Empty route.
		do
			create waypoints.make (4)
		end

feature -- Access

	waypoints: ARRAYED_LIST [INTEGER]
			-- Waypoint numbers, in order.

end
