note
	description: "[
		The robot's work as a behaviour: `start' launches a ROAMING_CONTROLLER guarded by a fresh
		stop signaler, `stop' raises it (the controller then stops the robot). Each start seeds
		the controller's random turns differently.
	]"

class
	ROAMING_BEHAVIOR

inherit
	BEHAVIOR

create
	make

feature {NONE} -- Initialization

	make (a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE; a_linear, a_angular: REAL_64;
			a_period: INTEGER_64; a_seed: INTEGER)
			-- Roaming with what `a_range' sees, driving `a_drive' at `a_linear' m/s, turning at
			-- `a_angular' rad/s, one step every `a_period' ns, random turns from `a_seed'.
		require
			positive_speeds: a_linear > 0.0 and a_angular > 0.0
			positive_period: a_period > 0
			non_negative_seed: a_seed >= 0
		do
			range_signaler := a_range
			drive := a_drive
			linear_speed := a_linear
			angular_speed := a_angular
			period := a_period
			seed := a_seed
		ensure
			not_running: not is_running
		end

feature -- Access

	range_signaler: separate RANGE_SIGNALER
			-- Obstacles.

	drive: separate DIFFERENTIAL_DRIVE
			-- The robot's velocity commands.

	linear_speed, angular_speed: REAL_64
			-- Forward speed (m/s) and turn rate (rad/s).

	period: INTEGER_64
			-- Nanoseconds between two steps of the controller.

	seed: INTEGER
			-- Seed of the first run's random turns.

feature {NONE} -- Implementation

	launch (a_stop: separate STOP_SIGNALER)
			-- <Precursor>
		local
			controller: separate ROAMING_CONTROLLER
		do
			create controller.make (a_stop, range_signaler, drive, linear_speed, angular_speed, period, seed + start_count)
			run (controller)
		end

	run (a_controller: separate ROAMING_CONTROLLER)
			-- Set `a_controller' going.
		do
			a_controller.run
		end

end
