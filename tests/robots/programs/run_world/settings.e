class
	SETTINGS

create
	make

feature

	make
			-- Print what ROBOT_ENVIRONMENT says about this run.
		local
			env: ROBOT_ENVIRONMENT
			i: INTEGER
		do
			create env
			print ("robot " + env.namespace + " (" + env.main_robot.out + " of " + env.robot_count.out + ")%N")
			from i := 1 until i > env.robot_count loop
				print (env.namespace_of (i) + " " + env.max_linear_of (i).out + " " + env.max_angular_of (i).out + "%N")
				i := i + 1
			end
			print ("simulated " + env.is_simulated.out + " ros2 " + env.is_ros2.out + "%N")
			print ("goal " + env.has_goal.out + " " + env.goal_x.out + " " + env.goal_y.out + "%N")
			print ("station " + env.has_charging_station.out + " " + env.station_x.out + " " + env.station_y.out + " " + env.station_radius.out + "%N")
			print ("duration " + env.duration.out + "%N")
		end

end
