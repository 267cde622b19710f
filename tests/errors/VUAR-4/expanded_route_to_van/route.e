note
	description: "The stops of a delivery route, copied on assignment."

expanded class
	ROUTE

inherit
	ANY
		redefine
			default_create
		end

feature -- Initialization

	default_create
			-- A route with no stop.
		do
			create stops.make (4)
		end

feature -- Access

	stops: ARRAYED_LIST [INTEGER]
			-- Numbers of the stops, in order.

	length: INTEGER
			-- Number of stops.
		do
			Result := stops.count
		end

end
