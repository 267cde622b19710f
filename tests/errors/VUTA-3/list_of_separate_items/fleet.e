note
	description: "Launches a fleet of drones, each on its own processor."

class
	FLEET

create
	make

feature {NONE} -- Initialization

	make
			-- Create three drones and let them take off.
		local
			l_drone: separate DRONE
			i: INTEGER
		do
			create drones.make (3)
			from
				i := 1
			until
				i > 3
			loop
				create l_drone.make (i)
				drones.extend (l_drone)
				i := i + 1
			end
			across drones as c loop
				launch (c.item)
				c.item.take_off -- E: VUTA(3)
			end
			drones.first.land -- E: VUTA(3)
		end

feature -- Basic operations

	launch (a_drone: separate DRONE)
			-- Let `a_drone' take off.
		do
			a_drone.take_off
		end

feature -- Access

	drones: ARRAYED_LIST [separate DRONE]
			-- The fleet.

end
