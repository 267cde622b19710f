note
	description: "Pings every robot of a team."

class
	ROLL_CALL

create
	make

feature {NONE} -- Initialization

	make
			-- Create two robots and ping them.
		local
			l_robot: separate ROBOT
		do
			create robots.make (2)
			create l_robot.make (1)
			robots.extend (l_robot)
			create l_robot.make (2)
			robots.extend (l_robot)
			across robots as c loop
				separate c.item as c do -- E: FRESH_IDENTIFIER
					print ("robot reserved%N")
				end
				separate c.item as r do
					r.ping
				end
			end
		end

feature -- Access

	robots: ARRAYED_LIST [separate ROBOT]
			-- The team.

end
