note
	description: "[
		The paper's simple controller: go straight while the way is clear, turn away from an
		obstacle, stop on an emergency. Each behaviour is a guarded routine over separate
		signalers whose wait condition says when it applies.

		The paper's routines work on a ROBOT (`make_for_robot'): `go' (apply the default speed
		when nothing is in front), `turn' (turn away from an obstacle while the robot moves) and
		`stop' (stop the moving robot once a stop is requested). The controller's loops take no
		arguments: `go_straight', `turn_to_avoid_obstacles' and `stop_on_emergency' repeat their
		routine until the stop signaler fires. In the paper's exploration three controllers are
		launched together, one loop each (EXPLORATION_BEHAVIOR's `launch').

		A controller made with `make' or `make_with_maneuver' works on a DIFFERENTIAL_DRIVE
		instead, and its loops repeat the library's tuned routines: `cruise' (forward while clear),
		`avoid' (timed escape maneuvers away from obstacles and holes, with random turn durations,
		shared through a MANEUVER_SIGNALER) and `halt'; `run' alternates `drive_straight' and
		`turn_away' on one processor. Every guard of a loop also holds once the stop is requested,
		so every loop ends. Not a busy loop: a guard that stays true runs every `period'
		nanoseconds (the controller sleeps on the runtime's clock between iterations), so cmd_vel
		gets at most one command per period from each controller.
	]"

class
	SIMPLE_CONTROLLER

create
	make, make_with_maneuver, make_for_robot

feature {NONE} -- Initialization

	make (a_stop: separate STOP_SIGNALER; a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE;
			a_linear, a_angular: REAL_64; a_period: INTEGER_64)
			-- Controller driving at `a_linear' m/s, turning at `a_angular' rad/s, every `a_period' ns,
			-- with a maneuver signaler of its own.
		require
			positive_speeds: a_linear > 0.0 and a_angular > 0.0
			non_negative_period: a_period >= 0
		local
			m: separate MANEUVER_SIGNALER
		do
			create m.make
			make_with_maneuver (a_stop, a_range, m, a_drive, a_linear, a_angular, a_period)
		end

	make_with_maneuver (a_stop: separate STOP_SIGNALER; a_range: separate RANGE_SIGNALER;
			a_maneuver: separate MANEUVER_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE;
			a_linear, a_angular: REAL_64; a_period: INTEGER_64)
			-- Like `make', sharing the maneuver signaler `a_maneuver' with other controllers.
		require
			positive_speeds: a_linear > 0.0 and a_angular > 0.0
			non_negative_period: a_period >= 0
		do
			stop_signaler := a_stop
			range_signaler := a_range
			maneuver_signaler := a_maneuver
			drive := a_drive
			linear_speed := a_linear
			angular_speed := a_angular
			period := a_period
			create clock.make
			create random.make
			random.start
			min_turn_angle := 0.7
			max_turn_angle := 2.6
			backoff_time := 0.4
		end

	make_for_robot (a_stop: separate STOP_SIGNALER; a_robot: separate DIFF_DRIVE_ROBOT)
			-- Controller of `a_robot' (the paper's `go', `turn' and `stop'), with its range signaler,
			-- odometry and drive, at its top speeds, every `Default_period'.
		do
			make (a_stop, a_robot.range_signaler, a_robot.drive, a_robot.max_linear, a_robot.max_angular, Default_period)
			controlled_robot := a_robot
			odometry_signaler := a_robot.odometry
		ensure
			has_robot: controlled_robot /= Void
		end

feature -- Access

	controlled_robot: detachable separate ROBOT
			-- The robot of `make_for_robot' (Void: the controller commands `drive').

	odometry_signaler: detachable separate ODOMETRY_SIGNALER
			-- The robot's motion, with `controlled_robot'.

	Default_period: INTEGER_64 = 50_000_000
			-- 50 ms: the period of `make_for_robot'.

	stop_signaler: separate STOP_SIGNALER
			-- Emergency stop.

	range_signaler: separate RANGE_SIGNALER
			-- Obstacles.

	maneuver_signaler: separate MANEUVER_SIGNALER
			-- Timed escape maneuvers under way.

	drive: separate DIFFERENTIAL_DRIVE
			-- Where commands go.

	linear_speed, angular_speed: REAL_64
			-- Forward speed and turn rate commanded.

	period: INTEGER_64
			-- Nanoseconds between iterations of the loops.

	iteration_count: INTEGER
			-- Iterations of the loop run so far.

	min_turn_angle, max_turn_angle: REAL_64
			-- Bounds of a random escape turn (radians): each turn lasts the time needed to turn by
			-- an angle drawn uniformly between them at `angular_speed'.

	backoff_time: REAL_64
			-- Seconds spent backing away from a hole before turning.

feature -- Status report

	is_finished: BOOLEAN
			-- Has the loop seen the stop request?

feature -- Element change

	set_turn_angles (a_min, a_max: REAL_64)
			-- Escape turns turn by between `a_min' and `a_max' radians.
		require
			valid: 0.0 < a_min and a_min <= a_max
		do
			min_turn_angle := a_min
			max_turn_angle := a_max
		end

	set_backoff_time (a_seconds: REAL_64)
			-- Back away from a hole for `a_seconds'.
		require
			non_negative: a_seconds >= 0.0
		do
			backoff_time := a_seconds
		end

	set_seed (a_seed: INTEGER)
			-- Restart the random turn durations from `a_seed'.
		require
			non_negative: a_seed >= 0
		do
			random.set_seed (a_seed)
			random.start
		end

feature -- Guarded behaviours

	go (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; robot: separate ROBOT)
			-- Go straight when nothing is in front (the paper's).
		require
			not s_sig.is_stop_requested
			not r_sig.has_obstacle
		do
			robot.apply_default_speed
		end

	turn (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; o_sig: separate ODOMETRY_SIGNALER;
			robot: separate ROBOT)
			-- Turn away from an obstacle in front while the robot moves (the paper's).
		require
			not s_sig.is_stop_requested
			r_sig.has_obstacle
			o_sig.is_moving
		do
			if r_sig.is_obstacle_left then
				robot.turn_right
			else
				robot.turn_left
			end
		end

	stop (s_sig: separate STOP_SIGNALER; o_sig: separate ODOMETRY_SIGNALER; robot: separate ROBOT)
			-- Stop the moving robot once a stop is requested (the paper's).
		require
			s_sig.is_stop_requested
			o_sig.is_moving
		do
			robot.stop
		end

	drive_straight (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Drive forward when nothing is in front.
		require
			not s_sig.is_stop_requested
			not r_sig.has_obstacle
		do
			a_drive.send (linear_speed, 0.0)
		end

	turn_away (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Turn in place away from an obstacle in front (to the right when it is on the left).
		require
			not s_sig.is_stop_requested
			r_sig.has_obstacle
		do
			if r_sig.is_obstacle_left then
				a_drive.send (0.0, - angular_speed)
			else
				a_drive.send (0.0, angular_speed)
			end
		end

	halt (s_sig: separate STOP_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Stop the robot once a stop is requested.
		require
			s_sig.is_stop_requested
		do
			a_drive.stop
			is_finished := True
		end

	cruise (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; m_sig: separate MANEUVER_SIGNALER;
			a_drive: separate DIFFERENTIAL_DRIVE)
			-- Drive forward while the way is clear, the data fresh and no maneuver under way.
		require
			s_sig.is_stop_requested or (r_sig.is_clear and not r_sig.is_stale and not m_sig.is_active)
		do
			if s_sig.is_stop_requested then
				is_finished := True
			else
				a_drive.send (linear_speed, 0.0)
			end
		end

	avoid (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; m_sig: separate MANEUVER_SIGNALER;
			a_drive: separate DIFFERENTIAL_DRIVE)
			-- Escape from an obstacle in front or a hole under a ground sensor: back away from a
			-- hole, then turn away for a random time; keep turning while the way is still blocked.
		require
			s_sig.is_stop_requested or r_sig.has_obstacle or r_sig.has_ground_hole or m_sig.is_active
		local
			now: REAL_64
		do
			if s_sig.is_stop_requested then
				is_finished := True
			else
				now := clock.now
				if not m_sig.is_active or else (m_sig.linear > 0.0 and not r_sig.is_clear) then
					plan_escape (r_sig, m_sig, now)
				elseif m_sig.linear < 0.0 and r_sig.is_obstacle_behind then
					m_sig.advance (now)
				elseif m_sig.is_phase_over (now) then
					if m_sig.has_next_phase then
						m_sig.advance (now)
					elseif r_sig.has_obstacle or r_sig.has_ground_hole then
						m_sig.extend (now, uniform (0.2, 0.5))
					else
						m_sig.finish
					end
				end
				if m_sig.is_active then
					a_drive.send (m_sig.linear, m_sig.angular)
				end
			end
		end

	swerve (s_sig: separate STOP_SIGNALER; m_sig: separate MANEUVER_SIGNALER)
			-- Start a random turn, slowing down, unless a maneuver is under way (wandering).
		local
			direction: REAL_64
		do
			if s_sig.is_stop_requested then
				is_finished := True
			elseif not m_sig.is_active then
				direction := random_direction
				m_sig.start (linear_speed / 2.0, direction * angular_speed / 2.0, clock.now, turn_time)
			end
		end

feature -- Loops

	run
			-- Go straight or turn every `period' until the stop signaler fires; then stop the robot.
		do
			from
				is_finished := False
			until
				is_finished
			loop
				control (stop_signaler, range_signaler, drive)
				pause
			end
		ensure
			finished: is_finished
		end

	go_straight
			-- Until the stop signaler fires, drive straight ahead whenever the way is clear, every
			-- `period': the paper's `go' on `controlled_robot', or `cruise' on `drive'.
		do
			from
				is_finished := False
			until
				is_finished
			loop
				if attached controlled_robot as r then
					go_or_finish (stop_signaler, range_signaler, r)
				else
					cruise (stop_signaler, range_signaler, maneuver_signaler, drive)
				end
				iteration_count := iteration_count + 1
				pause
			end
		ensure
			finished: is_finished
		end

	turn_to_avoid_obstacles
			-- Until the stop signaler fires, turn away from obstacles, every `period': the paper's
			-- `turn' on `controlled_robot', or `avoid' (escape maneuvers, holes too) on `drive'.
		do
			from
				is_finished := False
			until
				is_finished
			loop
				if attached controlled_robot as r and attached odometry_signaler as o then
					turn_or_finish (stop_signaler, range_signaler, o, r)
				else
					avoid (stop_signaler, range_signaler, maneuver_signaler, drive)
				end
				iteration_count := iteration_count + 1
				pause
			end
		ensure
			finished: is_finished
		end

	stop_on_emergency
			-- Wait for the stop request, then stop the robot: the paper's `stop' on a moving
			-- `controlled_robot' (a robot at rest gets a stop too), or `halt' on `drive'.
		do
			is_finished := False
			if attached controlled_robot as r and attached odometry_signaler as o then
				stop_or_finish (stop_signaler, o, r)
			else
				halt (stop_signaler, drive)
			end
			iteration_count := iteration_count + 1
		ensure
			finished: is_finished
		end

	run_swerve (a_min_gap, a_max_gap: REAL_64)
			-- Every `a_min_gap' to `a_max_gap' seconds (at random), `swerve', until the stop signaler fires.
		require
			valid_gaps: 0.0 < a_min_gap and a_min_gap <= a_max_gap
		do
			from
				is_finished := False
			until
				is_finished
			loop
				clock.sleep (uniform (a_min_gap, a_max_gap))
				swerve (stop_signaler, maneuver_signaler)
				iteration_count := iteration_count + 1
			end
		ensure
			finished: is_finished
		end

feature {NONE} -- Implementation

	clock: TIMER
			-- The runtime's clock.

	random: RANDOM
			-- Turn durations and directions.

	control (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- One iteration: the behaviour whose guard holds (all three reserved together).
		do
			if s_sig.is_stop_requested then
				halt (s_sig, a_drive)
			elseif r_sig.has_obstacle then
				turn_away (s_sig, r_sig, a_drive)
			else
				drive_straight (s_sig, r_sig, a_drive)
			end
			iteration_count := iteration_count + 1
		end

	go_or_finish (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; a_robot: separate ROBOT)
			-- `go', or finish once the stop is requested.
		require
			s_sig.is_stop_requested or not r_sig.has_obstacle
		do
			if s_sig.is_stop_requested then
				is_finished := True
			else
				go (s_sig, r_sig, a_robot)
			end
		end

	turn_or_finish (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; o_sig: separate ODOMETRY_SIGNALER;
			a_robot: separate ROBOT)
			-- `turn', or finish once the stop is requested.
		require
			s_sig.is_stop_requested or (r_sig.has_obstacle and o_sig.is_moving)
		do
			if s_sig.is_stop_requested then
				is_finished := True
			else
				turn (s_sig, r_sig, o_sig, a_robot)
			end
		end

	stop_or_finish (s_sig: separate STOP_SIGNALER; o_sig: separate ODOMETRY_SIGNALER; a_robot: separate ROBOT)
			-- Once the stop is requested: `stop' the robot (at rest too), and finish.
		require
			s_sig.is_stop_requested
		do
			if o_sig.is_moving then
				stop (s_sig, o_sig, a_robot)
			else
				a_robot.stop
			end
			is_finished := True
		end

	plan_escape (r_sig: separate RANGE_SIGNALER; m_sig: separate MANEUVER_SIGNALER; a_now: REAL_64)
			-- Start the maneuver that gets away from what `r_sig' sees.
		local
			direction: REAL_64
		do
			if r_sig.has_ground_hole then
				if r_sig.is_hole_left and not r_sig.is_hole_right then
					direction := -1.0
				elseif r_sig.is_hole_right and not r_sig.is_hole_left then
					direction := 1.0
				else
					direction := random_direction
				end
				if r_sig.is_obstacle_behind or backoff_time = 0.0 then
					m_sig.start (0.0, direction * angular_speed, a_now, turn_time)
				else
					m_sig.start_two (- linear_speed / 2.0, 0.0, a_now, backoff_time,
						0.0, direction * angular_speed, turn_time)
				end
			else
				if r_sig.is_obstacle_left and not r_sig.is_obstacle_right then
					direction := -1.0
				elseif r_sig.is_obstacle_right and not r_sig.is_obstacle_left then
					direction := 1.0
				else
					direction := random_direction
				end
				m_sig.start (0.0, direction * angular_speed, a_now, turn_time)
			end
		end

	uniform (a_low, a_high: REAL_64): REAL_64
			-- A random number in [`a_low', `a_high'].
		do
			random.forth
			Result := a_low + (a_high - a_low) * random.double_item
		end

	turn_time: REAL_64
			-- Duration of a random escape turn (s).
		do
			Result := uniform (min_turn_angle, max_turn_angle) / angular_speed
		end

	random_direction: REAL_64
			-- 1 or -1 at random.
		do
			if uniform (0.0, 1.0) < 0.5 then
				Result := -1.0
			else
				Result := 1.0
			end
		end

	pause
			-- Sleep `period' nanoseconds on the runtime's clock (unless finished).
		do
			if not is_finished and period > 0 then
				(create {EXECUTION_ENVIRONMENT}).sleep (period)
			end
		end

end
