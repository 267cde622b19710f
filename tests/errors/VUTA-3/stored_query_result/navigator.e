note
	description: "Reports where a robot is and how much battery it has left."

class
	NAVIGATOR

create
	make

feature {NONE} -- Initialization

	make
			-- Create a robot and report on it.
		local
			l_robot: separate ROBOT
		do
			create l_robot.make
			report (l_robot)
		end

feature -- Basic operations

	report (a_robot: separate ROBOT)
			-- Print the position and battery state of `a_robot'.
		local
			l_pose: separate POSE
			l_x: REAL_64
		do
			l_x := a_robot.pose.x
			print (a_robot.pose.y)
			l_pose := a_robot.pose
			print (l_pose.x) -- E: VUTA(3)
			if a_robot.battery.level < 20 then -- E: VUTA(3)
				print ("low battery%N")
			end
			check_battery (a_robot.battery)
			print (l_x)
		end

	check_battery (a_battery: separate BATTERY)
			-- Warn when `a_battery' is low.
		do
			if a_battery.level < 20 then
				print ("low battery%N")
			end
		end

end
