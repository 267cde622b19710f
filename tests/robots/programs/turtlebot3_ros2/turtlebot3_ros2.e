note
	description: "[
		A TURTLEBOT3_ROBOT on /tb3 (a ROS 2 run): sends 20 commands of 0.1 m/s 50 ms apart and ends.
	]"

class
	TURTLEBOT3_ROS2

create
	make

feature {NONE} -- Initialization

	make
			-- Drive a little.
		local
			robot: TURTLEBOT3_ROBOT
			i: INTEGER
		do
			create robot.make ("/tb3")
			print ("stamped " + robot.is_stamped.out + "%N")
			from i := 1 until i > 20 loop
				send (robot.drive, 0.1)
				(create {EXECUTION_ENVIRONMENT}).sleep (50_000_000)
				i := i + 1
			end
		end

feature {NONE} -- Implementation

	send (a_drive: separate DIFFERENTIAL_DRIVE; a_speed: REAL_64)
			-- Command `a_speed' forward.
		do
			a_drive.send (a_speed, 0.0)
		end

end
