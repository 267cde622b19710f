note
	description: "[
		A DIFF_DRIVE_ROBOT made from the robot profile beside it (robot.yaml: cmd_vel on /wheels/cmd
		as TwistStamped, odometry on /wheels/odom read reliably, limits): says what the profile gave,
		waits until its node's parameters `speed' (ROS_PARAMETER [REAL_64], 0 at first) and `mode'
		(ROS_PARAMETER [STRING]) are set from outside, then drives at that speed every 50 ms until stopped (a ROS 2 run, ended by Ctrl-C).
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
			create mode.make_with_text ("mode", "careful", "how to drive")
			create speed.make ("speed", 0.0, "forward speed of the commands (m/s)")
			wait_for_speed (speed, mode)
			from until False loop
				send (robot.drive, speed_of (speed))
				(create {EXECUTION_ENVIRONMENT}).sleep (50_000_000)
			end
		end

feature {NONE} -- Implementation

	speed: separate ROS_PARAMETER [REAL_64]
			-- The node's parameter `speed'.

	mode: separate ROS_PARAMETER [STRING]
			-- The node's parameter `mode'.

	wait_for_speed (a_speed: separate ROS_PARAMETER [REAL_64]; a_mode: separate ROS_PARAMETER [STRING])
			-- Wait until a speed and a mode were set.
		require
			set: a_speed.item > 0.0 and a_mode.change_count > 0
		local
			l_mode: STRING
		do
			create l_mode.make_from_separate (a_mode.item)
			print ("speed " + a_speed.item.out + " after " + a_speed.change_count.out + " change, mode " + l_mode + "%N")
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
