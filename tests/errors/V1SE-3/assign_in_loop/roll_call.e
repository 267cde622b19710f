note
	description: "Pings every robot of a team."

class
	ROLL_CALL

create
	make

feature {NONE} -- Initialization

	make
			-- Create three robots and ping them.
		local
			l_robot: separate ROBOT
			i: INTEGER
		do
			create robots.make (3)
			from
				i := 1
			until
				i > 3
			loop
				create l_robot.make (i)
				robots.extend (l_robot)
				i := i + 1
			end
			across robots as c loop
				separate c.item as r do
					r.ping
				end
			end
			separate robots.first as r do
				across robots as c loop
					r := c.item -- E: V1SE(3)
				end
				r.ping
			end
		end

feature -- Access

	robots: ARRAYED_LIST [separate ROBOT]
			-- The team.

end
