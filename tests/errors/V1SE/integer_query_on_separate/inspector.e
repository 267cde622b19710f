note
	description: "Inspects the state of a robot."

class
	INSPECTOR

create
	make

feature {NONE} -- Initialization

	make
			-- Create a robot and inspect it.
		local
			l_robot: separate ROBOT
		do
			create l_robot.make
			report (l_robot)
		end

feature -- Basic operations

	report (a_robot: separate ROBOT)
			-- Print the battery level and the position of `a_robot'.
		do
			separate a_robot.battery_level as level do -- E: V1SE
				print (level)
			end
			separate a_robot.pose as p do
				print (p.x)
			end
		end

end
