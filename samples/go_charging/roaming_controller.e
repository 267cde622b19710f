note
	description: "[
		The robot's work: roaming the arena. A cancellable control loop whose step goes straight
		while nothing is in front and otherwise turns away from the obstacle; once it starts a
		turn it keeps the direction until the way is clear and then for a random while longer,
		so the robot never dithers in a corner and its path crosses the arena instead of
		following the walls. When its stop signaler fires it stops the robot.
	]"

class
	ROAMING_CONTROLLER

inherit
	CANCELLABLE_CONTROL_LOOP
		rename
			make as make_loop
		redefine
			run, step
		end

create
	make

feature {NONE} -- Initialization

	make (a_stop: separate STOP_SIGNALER; a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE;
			a_linear, a_angular: REAL_64; a_period: INTEGER_64; a_seed: INTEGER)
			-- Roam at `a_linear' m/s, turning at `a_angular' rad/s, one step every `a_period' ns;
			-- random turn lengths from `a_seed'.
		require
			positive_speeds: a_linear > 0.0 and a_angular > 0.0
			positive_period: a_period > 0
			non_negative_seed: a_seed >= 0
		do
			make_loop (a_stop, a_period)
			range_signaler := a_range
			drive := a_drive
			linear_speed := a_linear
			angular_speed := a_angular
			create random.set_seed (a_seed)
			turn_direction := 1.0
		end

feature -- Access

	range_signaler: separate RANGE_SIGNALER
			-- Obstacles.

	drive: separate DIFFERENTIAL_DRIVE
			-- Where commands go.

	linear_speed, angular_speed: REAL_64
			-- Forward speed and turn rate commanded.

	turn_count: INTEGER
			-- Turns started so far.

feature -- Status report

	is_turning: BOOLEAN
			-- Is a turn under way?

feature -- Basic operations

	run
			-- Roam until the stop signaler fires, then stop the robot.
		do
			Precursor
			halt (drive)
		end

	step
			-- Go straight, or turn away from an obstacle.
		do
			roam (range_signaler, drive)
		end

feature {NONE} -- Implementation

	roam (a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- One step: keep turning while a turn is under way, start one when something is in
			-- front, else go straight.
		do
			if a_range.has_obstacle then
				if not is_turning then
					is_turning := True
					turn_count := turn_count + 1
					if a_range.is_obstacle_left and not a_range.is_obstacle_right then
						turn_direction := -1.0
					elseif a_range.is_obstacle_right and not a_range.is_obstacle_left then
						turn_direction := 1.0
					end
				end
				extra_steps := next_extra_steps
				a_drive.send (0.0, turn_direction * angular_speed)
			elseif is_turning and extra_steps > 0 then
				extra_steps := extra_steps - 1
				a_drive.send (0.0, turn_direction * angular_speed)
			else
				is_turning := False
				a_drive.send (linear_speed, 0.0)
			end
		end

	halt (a_drive: separate DIFFERENTIAL_DRIVE)
			-- Stop the robot.
		do
			a_drive.stop
		ensure
			stopped: a_drive.is_stopped
		end

	next_extra_steps: INTEGER
			-- Random number of steps to keep turning once the way is clear.
		do
			random.forth
			Result := random.item \\ (Max_extra_steps + 1)
		ensure
			in_range: 0 <= Result and Result <= Max_extra_steps
		end

	random: RANDOM
			-- Turn lengths.

	turn_direction: REAL_64
			-- 1: counter-clockwise, -1: clockwise.

	extra_steps: INTEGER
			-- Steps left to turn once the way is clear.

	Max_extra_steps: INTEGER = 15
			-- Longest extra turn, in steps.

invariant
	direction: turn_direction = 1.0 or turn_direction = -1.0

end
