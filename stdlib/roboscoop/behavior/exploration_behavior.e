note
	description: "[
		Exploration, with the structure of the Roboscoop paper (section IV): three separate
		SIMPLE_CONTROLLERs launched together, each repeating one guarded routine over the
		separate STOP, RANGE and MANEUVER signalers and the robot's drive until the stop:
		one goes straight while the way is clear (`cruise'), one gets away from obstacles and
		holes (`avoid': back off from a hole, then turn for a random time, away from the side
		that saw it), one stops the robot when the stop is requested (`stop_on_emergency').
		Random turn durations make the robot cover the floor instead of bouncing between the
		same walls. The guards that stay true run every `period' (50 ms by default).
		The paper's `start' and `launch': `start' (BEHAVIOR's) makes a fresh stop signaler and
		three controllers, and `launch' sets them going, one loop each: `go_straight',
		`turn_to_avoid_obstacles', `stop_on_emergency'. Made with `make_simple', the controllers
		are the paper's own: `go', `turn' and `stop' on the robot (SIMPLE_CONTROLLER's
		`make_for_robot'); made otherwise, the loops repeat the tuned `cruise', `avoid' and `halt'.
	]"

class
	EXPLORATION_BEHAVIOR

inherit
	BEHAVIOR
		rename
			launch as launch_controllers
		end

create
	make, make_for_robot, make_simple

feature {NONE} -- Initialization

	make (a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE; a_linear, a_angular: REAL_64)
			-- Explore with what `a_range' sees, driving `a_drive' at `a_linear' m/s, turning at `a_angular' rad/s.
		require
			positive_speeds: a_linear > 0.0 and a_angular > 0.0
		do
			range_signaler := a_range
			drive := a_drive
			linear_speed := a_linear
			angular_speed := a_angular
			period := Default_period
			seed := 1
		ensure
			not_running: not is_running
		end

	make_for_robot (a_robot: separate DIFF_DRIVE_ROBOT)
			-- Explore with `a_robot''s range signaler and drive, at its top speeds.
		do
			make (a_robot.range_signaler, a_robot.drive, a_robot.max_linear, a_robot.max_angular)
		end

	make_simple (a_robot: separate DIFF_DRIVE_ROBOT)
			-- The paper's exploration: three controllers of `a_robot' (`go', `turn', `stop').
		do
			make_for_robot (a_robot)
			robot := a_robot
		ensure
			not_running: not is_running
			simple: robot /= Void
		end

feature -- Access

	robot: detachable separate DIFF_DRIVE_ROBOT
			-- The robot of `make_simple' (Void: the tuned controllers).

	range_signaler: separate RANGE_SIGNALER
			-- Obstacles and holes.

	drive: separate DIFFERENTIAL_DRIVE
			-- The robot's velocity commands.

	linear_speed, angular_speed: REAL_64
			-- Cruising speed (m/s) and turn rate (rad/s).

	period: INTEGER_64
			-- Nanoseconds between two iterations of a controller whose guard stays true.

	seed: INTEGER
			-- Seed of the random turn durations.

	Default_period: INTEGER_64 = 50_000_000
			-- 50 ms: the rate of the Thymio's proximity sensors.

	maneuver_signaler: detachable separate MANEUVER_SIGNALER
			-- Escape maneuvers of the current run.

feature -- Element change

	set_period (a_period: INTEGER_64)
			-- Iterate every `a_period' nanoseconds (from the next `start').
		require
			positive: a_period > 0
		do
			period := a_period
		end

	set_seed (a_seed: INTEGER)
			-- Seed the random turn durations (from the next `start').
		require
			non_negative: a_seed >= 0
		do
			seed := a_seed
		end

feature -- Basic operations

	launch (a, b, c: separate SIMPLE_CONTROLLER)
			-- Set the three controllers going together (the paper's): `a' goes straight, `b' turns to
			-- avoid obstacles, `c' stops the robot on an emergency.
		do
			a.go_straight
			b.turn_to_avoid_obstacles
			c.stop_on_emergency
		end

feature {NONE} -- Implementation

	launch_controllers (a_stop: separate STOP_SIGNALER)
			-- <Precursor>
		local
			m: separate MANEUVER_SIGNALER
			straight, avoider, emergency: separate SIMPLE_CONTROLLER
		do
			create m.make
			maneuver_signaler := m
			if attached robot as r then
				create straight.make_for_robot (a_stop, r)
				create avoider.make_for_robot (a_stop, r)
				create emergency.make_for_robot (a_stop, r)
			else
				create straight.make_with_maneuver (a_stop, range_signaler, m, drive, linear_speed, angular_speed, period)
				create avoider.make_with_maneuver (a_stop, range_signaler, m, drive, linear_speed, angular_speed, period)
				create emergency.make_with_maneuver (a_stop, range_signaler, m, drive, linear_speed, angular_speed, period)
				seed_avoider (avoider)
			end
			launch (straight, avoider, emergency)
			launch_more (a_stop, m)
		end

	seed_avoider (a_avoider: separate SIMPLE_CONTROLLER)
			-- Seed the random turns of `a_avoider'.
		do
			a_avoider.set_seed (seed)
		end

	launch_more (a_stop: separate STOP_SIGNALER; a_maneuver: separate MANEUVER_SIGNALER)
			-- Launch further controllers sharing `a_maneuver' (none here).
		do
		end

end
