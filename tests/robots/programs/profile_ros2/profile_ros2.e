note
	description: "[
		A DIFF_DRIVE_ROBOT made from the robot profile beside it (robot.yaml: cmd_vel on /wheels/cmd
		as TwistStamped, odometry on /wheels/odom read reliably, limits): says what the profile gave,
		then drives at 0.1 m/s every 50 ms until stopped (a ROS 2 run, ended by Ctrl-C).
	]"

class
	PROFILE_ROS2

create
	make

feature {NONE} -- Initialization

	make
			-- Drive as the profile says, until stopped.
		local
			robot: DIFF_DRIVE_ROBOT
			env: ROBOT_ENVIRONMENT
		do
			create env
			create robot.make_from_profile (env.namespace)
			print ("profile " + env.has_profile.out + " stamped " + robot.is_stamped.out)
			print (" max " + robot.max_linear.out + " " + robot.max_angular.out)
			print (" cmd " + robot.topic ("cmd_vel") + " odom " + robot.topic ("odom") + "%N")
			listen (robot.odometry)
			from until False loop
				send (robot.drive, 0.1)
				(create {EXECUTION_ENVIRONMENT}).sleep (50_000_000)
			end
		end

feature {NONE} -- Implementation

	listen (a_odometry: separate ODOMETRY_SIGNALER)
			-- Make sure the odometry is subscribed.
		do
			a_odometry.do_nothing
		end

	send (a_drive: separate DIFFERENTIAL_DRIVE; a_speed: REAL_64)
			-- Command `a_speed' forward.
		do
			a_drive.send (a_speed, 0.0)
		end

end
