note
	description: "[
		Drives a differential-drive robot from point to point on its odometry: it turns in place
		toward the point, then drives to it with a PID controller on the heading and a forward
		speed that falls with the distance. One step every `period' nanoseconds, each reserving
		the odometry signaler, the drive and the stop signaler together.
	]"

class
	PILOT

create
	make

feature {NONE} -- Initialization

	make (a_odometry: separate ODOMETRY_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE;
			a_stop: separate STOP_SIGNALER; a_speed: REAL_64; a_period: INTEGER_64)
			-- Pilot reading `a_odometry', commanding `a_drive' at up to `a_speed' m/s, cancelled by `a_stop'.
		require
			positive_speed: a_speed > 0.0
			positive_period: a_period > 0
		do
			odometry := a_odometry
			drive := a_drive
			stop := a_stop
			speed := a_speed
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

	speed: REAL_64
			-- Largest forward speed (m/s).

	period: INTEGER_64
			-- Nanoseconds between two steps.

	x, y: REAL_64
			-- Position at the last step.

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
			is_aligned := False
			heading.reset
			from
			until
				has_arrived or is_cancelled
			loop
				steer (odometry, drive, stop)
				if not (has_arrived or is_cancelled) then
					(create {EXECUTION_ENVIRONMENT}).sleep (period)
				end
			end
		ensure
			ended: has_arrived xor is_cancelled
		end

feature {NONE} -- Implementation

	steer (a_odometry: separate ODOMETRY_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE; a_stop: separate STOP_SIGNALER)
			-- One step: stop when arrived or stopped, else turn toward the target until facing
			-- it, then drive to it.
		require
			located: a_odometry.has_reading
		local
			dx, dy, distance, error, turn: REAL_64
		do
			x := a_odometry.x
			y := a_odometry.y
			dx := target_x - x
			dy := target_y - y
			distance := math.sqrt (dx * dx + dy * dy)
			error := math.angle_difference (math.arc_tangent_2 (dy, dx), a_odometry.theta)
			if a_stop.is_stop_requested then
				a_drive.stop
				is_cancelled := True
			elseif distance <= tolerance then
				a_drive.stop
				has_arrived := True
			elseif not is_aligned then
				if error.abs < Aligned_angle then
					is_aligned := True
					a_drive.send (0.0, 0.0)
				else
					turn := Max_turn.min (Heading_gain * error.abs + Min_turn)
					if error < 0.0 then
						turn := - turn
					end
					a_drive.send (0.0, turn)
				end
			else
				a_drive.send ((Approach_gain * distance).min (speed) * math.cosine (error).max (0.0),
					heading.output (error, period / 1.0e9))
			end
		end

	is_aligned: BOOLEAN
			-- Has the robot turned toward the target?

	odometry: separate ODOMETRY_SIGNALER
	drive: separate DIFFERENTIAL_DRIVE
	stop: separate STOP_SIGNALER
			-- What the pilot reads and commands.

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

	Min_turn: REAL_64 = 0.1
			-- Smallest turn rate while turning in place (rad/s).

	Aligned_angle: REAL_64 = 0.05
			-- Heading error (rad) under which the robot counts as facing the target.

	Approach_gain: REAL_64 = 0.8
			-- Forward speed per metre of distance (1/s).

end
