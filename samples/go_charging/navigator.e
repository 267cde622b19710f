note
	description: "[
		Drives a differential-drive robot to a point: a PID controller turns the heading toward
		the point, the forward speed falls with the distance and is zero while the heading is
		far off. One step every `period' nanoseconds, each reserving the odometry and range
		signalers, the drive and the stop signaler together. An obstacle in front starts a
		detour: turn away from it until the way is clear, go straight a little, aim again.
	]"

class
	NAVIGATOR

create
	make

feature {NONE} -- Initialization

	make (a_odometry: separate ODOMETRY_SIGNALER; a_range: separate RANGE_SIGNALER;
			a_drive: separate DIFFERENTIAL_DRIVE; a_stop: separate STOP_SIGNALER; a_period: INTEGER_64)
			-- Navigator reading `a_odometry' and `a_range', commanding `a_drive', cancelled by `a_stop'.
		require
			positive_period: a_period > 0
		do
			odometry := a_odometry
			range := a_range
			drive := a_drive
			stop := a_stop
			period := a_period
			create heading.make (Heading_gain, 0.0, Heading_damping)
			heading.set_output_limit (Max_turn)
			create math
		end

feature -- Access

	target_x, target_y: REAL_64
			-- Where the robot goes.

	tolerance: REAL_64
			-- Distance to the target that counts as arrived (m).

	period: INTEGER_64
			-- Nanoseconds between two steps.

	step_count: INTEGER
			-- Steps of the last `go_to'.

feature -- Status report

	has_arrived: BOOLEAN
			-- Did the last `go_to' reach its target?

	is_cancelled: BOOLEAN
			-- Was the last `go_to' ended by the stop signaler?

feature -- Basic operations

	go_to (a_x, a_y, a_tolerance: REAL_64)
			-- Drive to (`a_x', `a_y') until within `a_tolerance' of it, or until stopped; the
			-- robot is at rest afterwards.
		require
			positive_tolerance: a_tolerance > 0.0
		do
			target_x := a_x
			target_y := a_y
			tolerance := a_tolerance
			has_arrived := False
			is_cancelled := False
			step_count := 0
			heading.reset
			detour_steps := 0
			from
			until
				has_arrived or is_cancelled
			loop
				steer (odometry, range, drive, stop)
				if not (has_arrived or is_cancelled) then
					(create {EXECUTION_ENVIRONMENT}).sleep (period)
				end
			end
		ensure
			ended: has_arrived xor is_cancelled
		end

feature {NONE} -- Implementation

	steer (a_odometry: separate ODOMETRY_SIGNALER; a_range: separate RANGE_SIGNALER;
			a_drive: separate DIFFERENTIAL_DRIVE; a_stop: separate STOP_SIGNALER)
			-- One step: stop when arrived or stopped, else go on with a detour around an
			-- obstacle, else head for the target (turning in place when it is far off to a side).
		require
			located: a_odometry.has_reading
		local
			dx, dy, distance, error, v: REAL_64
		do
			step_count := step_count + 1
			dx := target_x - a_odometry.x
			dy := target_y - a_odometry.y
			distance := math.sqrt (dx * dx + dy * dy)
			if a_stop.is_stop_requested then
				a_drive.stop
				is_cancelled := True
			elseif distance <= tolerance then
				a_drive.stop
				has_arrived := True
			else
				error := math.angle_difference (math.arc_tangent_2 (dy, dx), a_odometry.theta)
				if detour_steps > 0 then
					detour (a_range, a_drive)
				elseif error.abs < Align_angle and a_range.has_obstacle then
					if a_range.is_obstacle_left then
						detour_direction := -1.0
					else
						detour_direction := 1.0
					end
					detour_steps := Detour_length
					detour (a_range, a_drive)
				else
					if error.abs < Align_angle then
						v := (Approach_gain * distance).min (Cruise_speed) * math.cosine (error)
					end
					a_drive.send (v, heading.output (error, period / 1.0e9))
				end
			end
		end

	detour (a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Go around an obstacle in front: turn away from it until the way is clear, then
			-- go straight for `detour_steps' steps before heading for the target again.
		require
			detouring: detour_steps > 0
		do
			if a_range.has_obstacle then
				a_drive.send (0.0, detour_direction * Max_turn)
			else
				a_drive.send (Cruise_speed, 0.0)
				detour_steps := detour_steps - 1
			end
		end

	detour_steps: INTEGER
			-- Straight steps left in the detour under way (0: none).

	detour_direction: REAL_64
			-- Turn direction of the detour (1: counter-clockwise, -1: clockwise).

	odometry: separate ODOMETRY_SIGNALER
	range: separate RANGE_SIGNALER
	drive: separate DIFFERENTIAL_DRIVE
	stop: separate STOP_SIGNALER
			-- What the navigator reads and commands.

	heading: PID_CONTROLLER
			-- Turn rate from the heading error.

	math: ANGLE_MATH
			-- Angle helpers.

feature {NONE} -- Constants

	Heading_gain: REAL_64 = 2.0
	Heading_damping: REAL_64 = 0.05
			-- PID gains on the heading error (rad -> rad/s).

	Max_turn: REAL_64 = 1.5
			-- Largest turn rate commanded (rad/s).

	Align_angle: REAL_64 = 0.5
			-- Heading error (rad) beyond which the robot turns in place.

	Approach_gain: REAL_64 = 0.8
			-- Forward speed per metre of distance (1/s).

	Cruise_speed: REAL_64 = 0.12
			-- Largest forward speed (m/s).

	Detour_length: INTEGER = 10
			-- Straight steps of a detour.

end
