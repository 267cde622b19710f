note
	description: "[
		A DIFF_DRIVE_ROBOT made from the robot profile beside it (robot.yaml: cmd_vel on /wheels/cmd
		as TwistStamped, odometry on /wheels/odom read reliably, limits): says what the profile gave,
		waits until its node's parameter `speed' (ROS_PARAMETER, 0 at first) is set from outside, then
		drives at that speed every 50 ms until stopped (a ROS 2 run, ended by Ctrl-C).
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
			create speed.make ("speed", 0.0, "forward speed of the commands (m/s)")
			wait_for_speed (speed)
			from until False loop
				send (robot.drive, speed_of (speed))
				(create {EXECUTION_ENVIRONMENT}).sleep (50_000_000)
			end
		end

feature {NONE} -- Implementation

	speed: separate ROS_PARAMETER [REAL_64]
			-- The node's parameter `speed'.

	wait_for_speed (a_speed: separate ROS_PARAMETER [REAL_64])
			-- Wait until a speed was set.
		require
			set: a_speed.item > 0.0
		do
			print ("speed " + a_speed.item.out + " after " + a_speed.change_count.out + " change%N")
		end

	speed_of (a_speed: separate ROS_PARAMETER [REAL_64]): REAL_64
			-- The speed now.
		do
			Result := a_speed.item
		end

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
