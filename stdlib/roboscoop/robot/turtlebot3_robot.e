note
	description: "[
		A TurtleBot3 (burger) under a topic namespace, with the topics of its ROS 2 bringup
		(ROBOTIS-GIT/turtlebot3, turtlebot3_node/src/turtlebot3.cpp and odometry.cpp,
		sensors/battery_state.cpp; the LDS laser driver): cmd_vel (geometry_msgs/Twist on Humble,
		TwistStamped from Jazzy on, as the bringup of each distribution takes it), odom, scan and
		battery_state. `range_signaler' sees the laser scan as obstacle sectors. Speed limits of the
		burger: 0.22 m/s, 2.84 rad/s.
	]"

class
	TURTLEBOT3_ROBOT

inherit
	DIFF_DRIVE_ROBOT
		redefine
			make, default_max_linear, default_max_angular
		end

create
	make, make_with_limits

feature {NONE} -- Initialization

	make (a_namespace: separate STRING)
			-- TurtleBot3 under `a_namespace': Twist commands on Humble, TwistStamped on later
			-- distributions (ROBOT_ENVIRONMENT's `ros_distro').
		local
			env: ROBOT_ENVIRONMENT
		do
			create env
			make_with_limits (a_namespace, default_max_linear, default_max_angular, env.takes_stamped_commands)
		end

feature -- Access

	default_max_linear: REAL_64
			-- <Precursor>
		do
			Result := 0.22
		end

	default_max_angular: REAL_64
			-- <Precursor>
		do
			Result := 2.84
		end

end
