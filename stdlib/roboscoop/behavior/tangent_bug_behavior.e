note
	description: "[
		TangentBug (Kamon, Rivlin, Rimon 1998): reach a goal among unknown obstacles with a
		laser of limited range, or find that it cannot be reached. One TANGENT_BUG_CONTROLLER
		reserves the odometry, the laser, the drive and the navigation signaler at each step
		and lets a TANGENT_BUG_PLANNER decide: motion to goal through the local tangent graph,
		boundary following with d_followed and d_reach, the leave condition, and the goal
		reported unreachable after a full loop around an obstacle. The outcome is in `status'
		(a separate NAVIGATION_SIGNALER: wait on `is_finished'); `is_goal_reached' and
		`is_unreachable' ask it.
	]"

class
	TANGENT_BUG_BEHAVIOR

inherit
	BEHAVIOR

create
	make, make_for_namespace, make_for_robot

feature {NONE} -- Initialization

	make (a_odometry: separate ODOMETRY_SIGNALER; a_laser: separate LASER_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE;
			a_goal_x, a_goal_y: REAL_64)
			-- Go to (`a_goal_x', `a_goal_y') with `a_odometry' and `a_laser', commanding `a_drive'.
		do
			odometry := a_odometry
			laser := a_laser
			drive := a_drive
			goal_x := a_goal_x
			goal_y := a_goal_y
			max_linear := a_drive.max_linear
			max_angular := a_drive.max_angular
			robot_radius := Default_radius
			period := Default_period
			create status.make
		ensure
			not_running: not is_running
		end

	make_for_namespace (a_namespace: separate STRING; a_goal_x, a_goal_y, a_max_linear, a_max_angular: REAL_64)
			-- Go to (`a_goal_x', `a_goal_y') with the robot whose topics (odom, scan, cmd_vel) are under
			-- `a_namespace' ("/robot1" or ""), at most at `a_max_linear' m/s and `a_max_angular' rad/s.
		require
			positive_limits: a_max_linear > 0.0 and a_max_angular > 0.0
		local
			ns: STRING
			o: separate ODOMETRY_SIGNALER
			l: separate LASER_SIGNALER
			d: separate DIFFERENTIAL_DRIVE
		do
			create ns.make_from_separate (a_namespace)
			create o.make (ns + "/odom")
			create l.make (ns + "/scan")
			create d.make (ns + "/cmd_vel", a_max_linear, a_max_angular)
			make (o, l, d, a_goal_x, a_goal_y)
		end

	make_for_robot (a_robot: separate DIFF_DRIVE_ROBOT; a_goal_x, a_goal_y: REAL_64)
			-- Go to (`a_goal_x', `a_goal_y') with `a_robot''s odometry, laser and drive.
		do
			make (a_robot.odometry, a_robot.laser, a_robot.drive, a_goal_x, a_goal_y)
		end

feature -- Access

	odometry: separate ODOMETRY_SIGNALER
			-- The robot's pose.

	laser: separate LASER_SIGNALER
			-- The robot's laser.

	drive: separate DIFFERENTIAL_DRIVE
			-- The robot's velocity commands.

	status: separate NAVIGATION_SIGNALER
			-- Progress and outcome of the current run.

	goal_x, goal_y: REAL_64
			-- The goal.

	robot_radius: REAL_64
			-- The robot's radius (m).

	max_linear, max_angular: REAL_64
			-- Speed limits.

	period: INTEGER_64
			-- Nanoseconds between control steps.

	Default_radius: REAL_64 = 0.15
			-- Radius of the simulator's diff_drive robot.

	Default_period: INTEGER_64 = 50_000_000
			-- 50 ms.

feature -- Status report

	is_goal_reached: BOOLEAN
			-- Has the robot reached the goal?
		do
			Result := reached (status)
		end

	is_unreachable: BOOLEAN
			-- Has the behaviour found the goal unreachable?
		do
			Result := unreachable (status)
		end

	is_finished: BOOLEAN
			-- Is the run over (reached, unreachable or stopped)?
		do
			Result := finished (status)
		end

feature -- Element change

	set_robot_radius (a_radius: REAL_64)
			-- Set `robot_radius' (from the next `start').
		require
			positive: a_radius > 0.0
		do
			robot_radius := a_radius
		end

	set_period (a_period: INTEGER_64)
			-- Set `period' (from the next `start').
		require
			positive: a_period > 0
		do
			period := a_period
		end

feature -- Basic operations

	wait_until_finished
			-- Wait until the goal is reached, found unreachable, or the behaviour stopped.
		do
			await (status)
		end

feature {NONE} -- Implementation

	launch (a_stop: separate STOP_SIGNALER)
			-- <Precursor>
		local
			c: separate TANGENT_BUG_CONTROLLER
		do
			reset_status (status)
			create c.make (a_stop, odometry, laser, drive, status, goal_x, goal_y, robot_radius, max_linear, max_angular, period)
			run_controller (c)
		end

	run_controller (a_controller: separate TANGENT_BUG_CONTROLLER)
			-- Set `a_controller' going.
		do
			a_controller.run
		end

	reset_status (a_status: separate NAVIGATION_SIGNALER)
			-- Make `a_status' idle.
		do
			a_status.reset
		end

	reached (a_status: separate NAVIGATION_SIGNALER): BOOLEAN
			-- Does `a_status' say the goal is reached?
		do
			Result := a_status.is_goal_reached
		end

	unreachable (a_status: separate NAVIGATION_SIGNALER): BOOLEAN
			-- Does `a_status' say the goal is unreachable?
		do
			Result := a_status.is_unreachable
		end

	finished (a_status: separate NAVIGATION_SIGNALER): BOOLEAN
			-- Does `a_status' say the run is over?
		do
			Result := a_status.is_finished
		end

	await (a_status: separate NAVIGATION_SIGNALER)
			-- Wait until `a_status' is finished.
		require
			a_status.is_finished
		do
		end

end
