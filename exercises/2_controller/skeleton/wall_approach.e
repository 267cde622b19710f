note
	description: "[
		A controller that drives the robot straight ahead until something is in front, then
		stops it (exercise 2, README.md). Each step reserves the range signaler and the drive;
		the first waits, in its wait condition, until the sensors have reported.
		Complete `run' and `step'.
	]"

class
	WALL_APPROACH

create
	make

feature {NONE} -- Initialization

	make (a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- A controller reading `a_range' and commanding `a_drive'.
		do
			range := a_range
			drive := a_drive
		end

feature -- Access

	range: separate RANGE_SIGNALER
			-- What is around the robot.

	drive: separate DIFFERENTIAL_DRIVE
			-- Its wheels.

	Speed: REAL_64 = 0.1
			-- Forward speed (m/s).

	Period: REAL_64 = 0.1
			-- Seconds between two steps.

feature -- Status report

	is_done: BOOLEAN
			-- Has the robot stopped in front of something?

feature -- Basic operations

	run
			-- Wait for the sensors, then `step' every `Period' seconds until done.
		do
			-- TODO
		ensure
			done: is_done
		end

feature {NONE} -- Implementation

	step (a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Drive on at `Speed' while the way is clear; stop and be done when it is not.
		do
			-- TODO
		end

end
