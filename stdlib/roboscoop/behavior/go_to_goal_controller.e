note
	description: "[
		The controller of GO_TO_GOAL_BEHAVIOR: every `period' it reserves the stop signaler,
		the odometry, the drive and the navigation signaler together and steers with two PID
		controllers: the heading error gives the turn rate, the distance the forward speed
		(scaled down while the robot does not face the goal). It stops the robot and ends
		once within `tolerance' of the goal or when the stop is requested.
	]"

class
	GO_TO_GOAL_CONTROLLER

inherit
	ANGLE_MATH

create
	make

feature {NONE} -- Initialization

	make (a_stop: separate STOP_SIGNALER; a_odometry: separate ODOMETRY_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE;
			a_status: separate NAVIGATION_SIGNALER; a_goal_x, a_goal_y, a_tolerance, a_max_linear, a_max_angular: REAL_64;
			a_period: INTEGER_64)
			-- Controller driving to (`a_goal_x', `a_goal_y') within `a_tolerance', every `a_period' ns.
		require
			positive: a_tolerance > 0.0 and a_max_linear > 0.0 and a_max_angular > 0.0
			positive_period: a_period > 0
		do
			stop_signaler := a_stop
			odometry := a_odometry
			drive := a_drive
			status := a_status
			goal_x := a_goal_x
			goal_y := a_goal_y
			tolerance := a_tolerance
			period := a_period
			create heading_pid.make (3.0, 0.0, 0.15)
			heading_pid.set_output_limit (a_max_angular)
			create distance_pid.make (1.0, 0.05, 0.0)
			distance_pid.set_output_limit (a_max_linear)
			create clock.make
		end

feature -- Access

	goal_x, goal_y: REAL_64
			-- The goal.

	tolerance: REAL_64
			-- Distance that counts as reached (m).

	stop_signaler: separate STOP_SIGNALER
			-- Ends the run.

	odometry: separate ODOMETRY_SIGNALER
			-- The robot's pose.

	drive: separate DIFFERENTIAL_DRIVE
			-- Where commands go.

	status: separate NAVIGATION_SIGNALER
			-- Where the progress is reported.

	heading_pid, distance_pid: PID_CONTROLLER
			-- Turn rate from the heading error; forward speed from the distance.

	period: INTEGER_64
			-- Nanoseconds between iterations.

	path_length: REAL_64
			-- Distance travelled (m).

feature -- Status report

	is_finished: BOOLEAN
			-- Is the run over?

feature -- Basic operations

	run
			-- Iterate until the goal is reached or the stop request.
		do
			from
				is_finished := False
				last_time := clock.now
			until
				is_finished
			loop
				iterate (stop_signaler, odometry, drive, status)
				if not is_finished then
					(create {EXECUTION_ENVIRONMENT}).sleep (period)
				end
			end
		ensure
			finished: is_finished
		end

feature {NONE} -- Implementation

	clock: TIMER
			-- The runtime's clock.

	last_time: REAL_64
			-- Clock at the previous iteration.

	last_x, last_y: REAL_64
			-- Position at the previous iteration.

	has_position: BOOLEAN
			-- Is `last_x', `last_y' known?

	iterate (a_stop: separate STOP_SIGNALER; a_odometry: separate ODOMETRY_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE;
			a_status: separate NAVIGATION_SIGNALER)
			-- One control step, everything reserved together.
		local
			dx, dy, d, heading_error, v, w, dt, now: REAL_64
		do
			now := clock.now
			dt := (now - last_time).max (1.0e-3)
			last_time := now
			if a_stop.is_stop_requested then
				a_drive.stop
				if not a_status.is_finished then
					a_status.report (a_status.Stopped, a_status.distance_to_goal, path_length)
				end
				is_finished := True
			elseif a_odometry.is_stale then
				if not a_drive.is_stopped then
					a_drive.stop
				end
			else
				if has_position then
					path_length := path_length + sqrt ((a_odometry.x - last_x) ^ 2 + (a_odometry.y - last_y) ^ 2)
				end
				last_x := a_odometry.x
				last_y := a_odometry.y
				has_position := True
				dx := goal_x - a_odometry.x
				dy := goal_y - a_odometry.y
				d := sqrt (dx * dx + dy * dy)
				if d <= tolerance then
					a_drive.stop
					a_status.report (a_status.Goal_reached, d, path_length)
					is_finished := True
				else
					heading_error := angle_difference (arc_tangent_2 (dy, dx), a_odometry.theta)
					w := heading_pid.output (heading_error, dt)
					v := distance_pid.output (d, dt)
					if heading_error.abs > Pi / 2.0 then
						v := 0.0
					else
						v := v * cosine (heading_error)
					end
					a_drive.send (v, w)
					a_status.report (a_status.Motion_to_goal, d, path_length)
				end
			end
		end

end
