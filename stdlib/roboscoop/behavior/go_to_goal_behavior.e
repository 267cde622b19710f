note
	description: "[
		Drive to a goal position with no obstacle in the way: one GO_TO_GOAL_CONTROLLER
		(PID on the heading error and on the distance, from the odometry) commands the drive
		until the robot is within `tolerance' of the goal. The outcome is in `status' (a
		separate NAVIGATION_SIGNALER: wait on `is_finished'); `is_goal_reached' asks it.
	]"

class
	GO_TO_GOAL_BEHAVIOR

inherit
	BEHAVIOR

create
	make, make_for_namespace, make_for_robot

feature {NONE} -- Initialization

	make (a_odometry: separate ODOMETRY_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE; a_goal_x, a_goal_y: REAL_64)
			-- Go to (`a_goal_x', `a_goal_y') with the pose of `a_odometry', commanding `a_drive'.
		do
			odometry := a_odometry
			drive := a_drive
			goal_x := a_goal_x
			goal_y := a_goal_y
			max_linear := a_drive.max_linear
			max_angular := a_drive.max_angular
			tolerance := 0.1
			period := Default_period
			create status.make
		ensure
			not_running: not is_running
		end

	make_for_namespace (a_namespace: separate STRING; a_goal_x, a_goal_y, a_max_linear, a_max_angular: REAL_64)
			-- Go to (`a_goal_x', `a_goal_y') with the robot whose topics are under `a_namespace' ("/robot1" or ""),
			-- at most at `a_max_linear' m/s and `a_max_angular' rad/s.
		require
			positive_limits: a_max_linear > 0.0 and a_max_angular > 0.0
		local
			ns: STRING
			o: separate ODOMETRY_SIGNALER
			d: separate DIFFERENTIAL_DRIVE
		do
			create ns.make_from_separate (a_namespace)
			create o.make (ns + "/odom")
			create d.make (ns + "/cmd_vel", a_max_linear, a_max_angular)
			make (o, d, a_goal_x, a_goal_y)
		end

	make_for_robot (a_robot: separate DIFF_DRIVE_ROBOT; a_goal_x, a_goal_y: REAL_64)
			-- Go to (`a_goal_x', `a_goal_y') with `a_robot''s odometry and drive.
		do
			make (a_robot.odometry, a_robot.drive, a_goal_x, a_goal_y)
		end

feature -- Access

	odometry: separate ODOMETRY_SIGNALER
			-- The robot's pose.

	drive: separate DIFFERENTIAL_DRIVE
			-- The robot's velocity commands.

	status: separate NAVIGATION_SIGNALER
			-- Progress and outcome of the current run.

	goal_x, goal_y: REAL_64
			-- The goal.

	tolerance: REAL_64
			-- Distance to the goal that counts as reached (m).

	max_linear, max_angular: REAL_64
			-- Speed limits.

	period: INTEGER_64
			-- Nanoseconds between control steps.

	Default_period: INTEGER_64 = 50_000_000
			-- 50 ms.

feature -- Status report

	is_goal_reached: BOOLEAN
			-- Has the robot reached the goal?
		do
			Result := reached (status)
		end

	is_finished: BOOLEAN
			-- Is the run over (goal reached or stopped)?
		do
			Result := finished (status)
		end

feature -- Element change

	set_tolerance (a_tolerance: REAL_64)
			-- Set `tolerance' (from the next `start').
		require
			positive: a_tolerance > 0.0
		do
			tolerance := a_tolerance
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
			-- Wait until the goal is reached or the behaviour stopped.
		do
			await (status)
		end

feature {NONE} -- Implementation

	launch (a_stop: separate STOP_SIGNALER)
			-- <Precursor>
		local
			c: separate GO_TO_GOAL_CONTROLLER
		do
			reset_status (status)
			create c.make (a_stop, odometry, drive, status, goal_x, goal_y, tolerance, max_linear, max_angular, period)
			run_controller (c)
		end

	run_controller (a_controller: separate GO_TO_GOAL_CONTROLLER)
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
