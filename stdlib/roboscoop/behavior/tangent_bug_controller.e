note
	description: "[
		The controller of TANGENT_BUG_BEHAVIOR: every `period' it reserves the stop signaler,
		the odometry, the laser, the drive and the navigation signaler together, takes a local
		copy of a new scan, lets its TANGENT_BUG_PLANNER decide and sends the command. It stops
		the robot and ends when the planner has an outcome, when the stop is requested, and
		holds the robot still while the laser or the odometry is stale.
	]"

class
	TANGENT_BUG_CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_stop: separate STOP_SIGNALER; a_odometry: separate ODOMETRY_SIGNALER; a_laser: separate LASER_SIGNALER;
			a_drive: separate DIFFERENTIAL_DRIVE; a_status: separate NAVIGATION_SIGNALER;
			a_goal_x, a_goal_y, a_radius, a_max_linear, a_max_angular: REAL_64; a_period: INTEGER_64)
			-- Controller towards (`a_goal_x', `a_goal_y') for a robot of radius `a_radius', every `a_period' ns.
		require
			positive: a_radius > 0.0 and a_max_linear > 0.0 and a_max_angular > 0.0
			positive_period: a_period > 0
		do
			stop_signaler := a_stop
			odometry := a_odometry
			laser := a_laser
			drive := a_drive
			status := a_status
			period := a_period
			create planner.make (a_goal_x, a_goal_y, a_radius, a_max_linear, a_max_angular)
			create scan.make_unconnected
		end

feature -- Access

	stop_signaler: separate STOP_SIGNALER
			-- Ends the run.

	odometry: separate ODOMETRY_SIGNALER
			-- The robot's pose.

	laser: separate LASER_SIGNALER
			-- The robot's laser.

	drive: separate DIFFERENTIAL_DRIVE
			-- Where commands go.

	status: separate NAVIGATION_SIGNALER
			-- Where the progress is reported.

	planner: TANGENT_BUG_PLANNER
			-- The algorithm.

	period: INTEGER_64
			-- Nanoseconds between iterations.

	iteration_count: INTEGER
			-- Iterations run.

feature -- Status report

	is_finished: BOOLEAN
			-- Is the run over?

feature -- Basic operations

	run
			-- Iterate until an outcome or the stop request.
		do
			from
				is_finished := False
			until
				is_finished
			loop
				iterate (stop_signaler, odometry, laser, drive, status)
				if not is_finished then
					(create {EXECUTION_ENVIRONMENT}).sleep (period)
				end
			end
		ensure
			finished: is_finished
		end

feature {NONE} -- Implementation

	scan: LASER_SIGNALER
			-- Local copy of the latest scan.

	seen_scans: INTEGER
			-- `update_count' of the laser at the last copy.

	iterate (a_stop: separate STOP_SIGNALER; a_odometry: separate ODOMETRY_SIGNALER; a_laser: separate LASER_SIGNALER;
			a_drive: separate DIFFERENTIAL_DRIVE; a_status: separate NAVIGATION_SIGNALER)
			-- One decision, everything reserved together.
		local
			fresh: BOOLEAN
		do
			iteration_count := iteration_count + 1
			if a_stop.is_stop_requested then
				a_drive.stop
				if not a_status.is_finished then
					a_status.report (a_status.Stopped, planner.distance_to_goal, planner.path_length)
				end
				is_finished := True
			elseif a_odometry.is_stale or a_laser.is_stale then
				if not a_drive.is_stopped then
					a_drive.stop
				end
			else
				fresh := a_laser.update_count /= seen_scans
				if fresh then
					scan.copy_scan (a_laser)
					seen_scans := a_laser.update_count
				end
				planner.update (a_odometry.x, a_odometry.y, a_odometry.theta, scan, fresh)
				a_drive.send (planner.linear, planner.angular)
				a_status.report (planner.mode, planner.distance_to_goal, planner.path_length)
				if planner.is_finished then
					a_drive.stop
					is_finished := True
				end
			end
		end

end
