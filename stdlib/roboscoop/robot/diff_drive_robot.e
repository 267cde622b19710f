note
	description: "[
		A differential-drive robot under a topic namespace ("/robot1", or "" for none): its
		velocity commands (`drive': geometry_msgs/Twist on cmd_vel, or TwistStamped with
		`make_stamped'), its odometry (`odometry', from odom), its battery (`battery', from
		battery_state), its laser scanner seen as obstacle sectors (`range_signaler', from
		scan) and the whole scan (`laser'). Each part is a separate object on its own
		processor, so that controllers reserve only what they use; the robot object just makes
		and holds them. The odometry, battery and laser signalers subscribe on first use (a
		program that never asks for them does not pay for their messages). `make_from_profile'
		takes the topic names, the command type and the speed limits from the run's robot profile
		(robot.yaml, docs/ROBOTS.md).
	]"

class
	DIFF_DRIVE_ROBOT

inherit
	ROBOT

create
	make, make_stamped, make_with_limits, make_from_profile

feature {NONE} -- Initialization

	make (a_namespace: separate STRING)
			-- Robot under `a_namespace' taking Twist commands, with the default speed limits.
		do
			make_with_limits (a_namespace, default_max_linear, default_max_angular, False)
		end

	make_stamped (a_namespace: separate STRING)
			-- Robot under `a_namespace' taking TwistStamped commands, with the default speed limits.
		do
			make_with_limits (a_namespace, default_max_linear, default_max_angular, True)
		ensure
			stamped: is_stamped
		end

	make_from_profile (a_namespace: separate STRING)
			-- Robot under `a_namespace' as the run's robot profile describes it (robot.yaml beside
			-- the program, or `scoopc run --profile'): its topic names, Twist or TwistStamped, its
			-- speed limits. Without a profile: the simulated robot's limits and command type, or on
			-- ROS 2 the robot interface's names, Twist and ROBOT_ENVIRONMENT's limits.
		local
			env: ROBOT_ENVIRONMENT
		do
			create env
			is_from_profile := True
			make_with_limits (a_namespace, env.max_linear, env.max_angular, env.profile_stamped)
		ensure
			from_profile: is_from_profile
		end

	make_with_limits (a_namespace: separate STRING; a_max_linear, a_max_angular: REAL_64; a_stamped: BOOLEAN)
			-- Robot under `a_namespace' driven at most at `a_max_linear' m/s and `a_max_angular' rad/s,
			-- with TwistStamped commands when `a_stamped'.
		require
			positive_limits: a_max_linear > 0.0 and a_max_angular > 0.0
		do
			namespace := normalized (create {STRING}.make_from_separate (a_namespace))
			max_linear := a_max_linear
			max_angular := a_max_angular
			is_stamped := a_stamped
			if a_stamped then
				create drive.make_stamped (topic ("cmd_vel"), a_max_linear, a_max_angular)
			else
				create drive.make (topic ("cmd_vel"), a_max_linear, a_max_angular)
			end
			make_range_signaler
		ensure
			limits_set: max_linear = a_max_linear and max_angular = a_max_angular
			stamped_set: is_stamped = a_stamped
		end

feature -- Access

	namespace: STRING
			-- Topic prefix: empty, or "/" followed by the name ("/robot1").

	max_linear, max_angular: REAL_64
			-- Speed limits (m/s, rad/s).

	drive: separate DIFFERENTIAL_DRIVE
			-- Velocity commands (cmd_vel).

	odometry: separate ODOMETRY_SIGNALER
			-- Pose and speeds (odom), subscribed on first use.
		once ("OBJECT")
			create Result.make (topic ("odom"))
		end

	battery: separate BATTERY_SIGNALER
			-- Charge (battery_state), subscribed on first use.
		once ("OBJECT")
			create Result.make (topic ("battery_state"))
		end

	range_signaler: separate RANGE_SIGNALER
			-- Obstacles around the robot.

	laser: separate LASER_SIGNALER
			-- The whole laser scan (scan), subscribed on first use.
		once ("OBJECT")
			create Result.make (topic ("scan"))
		end

	topic (a_name: STRING): STRING
			-- Full name of the robot's topic `a_name' ("odom" -> "/robot1/odom", or the name the
			-- robot profile gives it).
		local
			env: ROBOT_ENVIRONMENT
		do
			if is_from_profile then
				create env
				Result := env.profile_topic (namespace, a_name)
			else
				Result := namespace + "/" + a_name
			end
		end

	default_max_linear: REAL_64
			-- Forward speed limit of `make' (m/s).
		do
			Result := 0.5
		end

	default_max_angular: REAL_64
			-- Turn rate limit of `make' (rad/s).
		do
			Result := 2.0
		end

feature -- Status report

	is_stamped: BOOLEAN
			-- Are velocity commands TwistStamped?

	is_from_profile: BOOLEAN
			-- Were topic names, command type and limits taken from the run's robot profile?

feature -- Basic operations

	apply_default_speed
			-- <Precursor>
			-- At `max_linear'. The same command again within `Repeat_period' is not resent, so a
			-- loop that calls it over and over does not flood cmd_vel.
		do
			command (max_linear, 0.0)
		end

	turn_left
			-- <Precursor>
			-- At `max_angular', looking at `range_signaler' every `Turn_period' (clear: `is_clear' and
			-- nothing in front within 1.5 times its obstacle distance); at most a full turn.
		do
			turn_until_clear (max_angular)
		end

	turn_right
			-- <Precursor>
		do
			turn_until_clear (- max_angular)
		end

	stop
			-- <Precursor>
			-- Always sent.
		do
			send_velocity (drive, 0.0, 0.0)
			last_linear := 0.0
			last_angular := 0.0
			last_sent_at := clock.now
		end

	go_to_charging_station
			-- <Precursor>
			-- To the station of the run (ROBOT_ENVIRONMENT), with a GO_TO_GOAL_BEHAVIOR on `odometry'
			-- and `drive'; returns once there.
		local
			env: ROBOT_ENVIRONMENT
			trip: GO_TO_GOAL_BEHAVIOR
		do
			create env
			if env.has_charging_station then
				create trip.make (odometry, drive, env.station_x, env.station_y)
				trip.set_tolerance ((env.station_radius / 2.0).max (0.02))
				trip.start
				trip.wait_until_finished
			end
		end

feature {NONE} -- Implementation

	Turn_period: REAL_64 = 0.05
			-- Seconds between two looks at the front while turning (and two turn commands).

	Repeat_period: REAL_64 = 0.2
			-- Seconds within which `command' does not repeat the last command.

	last_linear, last_angular, last_sent_at: REAL_64
			-- The last command of `command' or `stop', and when it was sent (runtime clock, s).

	clock: TIMER
			-- The runtime's clock.
		once ("OBJECT")
			create Result.make
		end

	command (a_linear, a_angular: REAL_64)
			-- Send `a_linear' m/s and `a_angular' rad/s, unless that was the last command and it is
			-- younger than `Repeat_period' (well inside the robots' 0.5 s command watchdogs).
		do
			if a_linear /= last_linear or a_angular /= last_angular or clock.now - last_sent_at >= Repeat_period
				or last_sent_at = 0.0
			then
				send_velocity (drive, a_linear, a_angular)
				last_linear := a_linear
				last_angular := a_angular
				last_sent_at := clock.now
			end
		end

	turn_until_clear (a_rate: REAL_64)
			-- Turn in place at `a_rate' rad/s until `range_signaler' sees the front clear, then stop;
			-- nothing when it is clear already. Gives up after a full turn plus a second.
		local
			stopwatch: TIMER
			turned: BOOLEAN
		do
			from
				create stopwatch.make
				stopwatch.start
			until
				is_front_clear (range_signaler) or stopwatch.has_elapsed (2.0 * {MATH_CONST}.Pi / a_rate.abs + 1.0)
			loop
				command (0.0, a_rate)
				turned := True
				stopwatch.sleep (Turn_period)
			end
			if turned then
				stop
			end
		end

	is_front_clear (a_range: separate RANGE_SIGNALER): BOOLEAN
			-- Floor under the robot and nothing in front within 1.5 times the obstacle distance (so
			-- that the robot leaves an obstacle at a wide angle)?
		do
			Result := a_range.is_clear and
				(a_range.nearest_front < 0.0 or a_range.nearest_front > 1.5 * a_range.obstacle_distance)
		end

	send_velocity (a_drive: separate DIFFERENTIAL_DRIVE; a_linear, a_angular: REAL_64)
			-- Command `a_linear' m/s and `a_angular' rad/s.
		do
			a_drive.send (a_linear, a_angular)
		end

	make_range_signaler
			-- Create `range_signaler' from the laser scans.
		do
			create range_signaler.make_laser_topic (topic ("scan"))
		end

	normalized (a_namespace: STRING): STRING
			-- `a_namespace' with one leading "/" and no trailing one; empty stays empty.
		do
			Result := a_namespace.twin
			from until Result.is_empty or else Result [Result.count] /= '/' loop
				Result.remove_tail (1)
			end
			from until Result.is_empty or else Result [1] /= '/' loop
				Result.remove_head (1)
			end
			if not Result.is_empty then
				Result.prepend_character ('/')
			end
		ensure
			empty_or_rooted: Result.is_empty or else (Result [1] = '/' and Result [Result.count] /= '/')
		end

end
