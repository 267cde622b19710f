note
	description: "[
		The robot settings of this run: which robot the program drives (its topic namespace), the
		other robots of a simulated world, their speed limits, and the world's goal and charging
		station. Set by `scoopc run' (`--robot', `--world', `--namespace', `--goal'); a program run
		with no robot sees one robot with no namespace.
	]"

class
	ROBOT_ENVIRONMENT

feature -- Access

	namespace: STRING
			-- Topic prefix of the program's robot ("/robot1"; empty when it has none).
		do
			Result := namespace_of (main_robot)
		ensure
			empty_or_rooted: Result.is_empty or else Result [1] = '/'
		end

	namespace_of (i: INTEGER): STRING
			-- Topic prefix of robot `i'.
		require
			valid_robot: 1 <= i and i <= robot_count
		external
			"Python"
		end

	robot_count: INTEGER
			-- Robots known to this run (at least 1).
		external
			"Python"
		ensure
			at_least_one: Result >= 1
		end

	main_robot: INTEGER
			-- Index of the program's robot (`--namespace').
		external
			"Python"
		ensure
			valid: 1 <= Result and Result <= robot_count
		end

	max_linear: REAL_64
			-- Largest forward speed of the program's robot (m/s).
		do
			Result := max_linear_of (main_robot)
		end

	max_angular: REAL_64
			-- Largest turn rate of the program's robot (rad/s).
		do
			Result := max_angular_of (main_robot)
		end

	max_linear_of (i: INTEGER): REAL_64
			-- Largest forward speed of robot `i' (m/s).
		require
			valid_robot: 1 <= i and i <= robot_count
		external
			"Python"
		end

	max_angular_of (i: INTEGER): REAL_64
			-- Largest turn rate of robot `i' (rad/s).
		require
			valid_robot: 1 <= i and i <= robot_count
		external
			"Python"
		end

	goal_x, goal_y: REAL_64
			-- The goal (world coordinates, m); 0 when there is none.
		external
			"Python"
		end

	station_x, station_y: REAL_64
			-- Centre of the charging station (m); 0 when there is none.
		external
			"Python"
		end

	station_radius: REAL_64
			-- Radius of the charging station (m); 0 when there is none.
		external
			"Python"
		end

	duration: REAL_64
			-- Seconds the run lasts (simulated seconds on the simulator); negative when unbounded.
		external
			"Python"
		end

	ros_distro: STRING
			-- The ROS 2 distribution of this run: "humble", "jazzy" or "lyrical" (`--ros-distro',
			-- else ROS_DISTRO, else "jazzy").
		external
			"Python"
		end

	profile_topic (a_namespace, a_name: STRING): STRING
			-- Full name of the robot topic `a_name' ("cmd_vel", "odom", "battery_state", "scan") for
			-- the robot under `a_namespace': the name the run's robot profile gives it (relative names
			-- under `a_namespace'), else `a_namespace' + "/" + `a_name'.
		external
			"Python"
		end

feature -- Output

	report (a_text: STRING)
			-- Tell the user `a_text' on the run's error output, as "scoopc: " + `a_text'.
		external
			"Python"
		end

feature -- Status report

	is_simulated: BOOLEAN
			-- Does the program drive the built-in simulator?
		external
			"Python"
		end

	is_ros2: BOOLEAN
			-- Does the program drive a ROS 2 robot?
		external
			"Python"
		end

	has_goal: BOOLEAN
			-- Is a goal given (by the world or `--goal')?
		external
			"Python"
		end

	has_charging_station: BOOLEAN
			-- Does the world have a charging station?
		external
			"Python"
		end

	has_profile: BOOLEAN
			-- Does this run have a robot profile (robot.yaml, `--profile'; ROS 2 runs only)?
		external
			"Python"
		end

	profile_stamped: BOOLEAN
			-- Does the program's robot take TwistStamped on cmd_vel, as its profile says (ROS 2), or
			-- as the simulated robot does (its world's `cmd_vel_stamped')?
		external
			"Python"
		end

	takes_stamped_commands: BOOLEAN
			-- Do ros2_control's diff_drive_controller and the TurtleBot3 bringup of this run's
			-- distribution take geometry_msgs/TwistStamped on cmd_vel (Jazzy and later)?
		do
			Result := not ros_distro.same_string ("humble")
		end

end
