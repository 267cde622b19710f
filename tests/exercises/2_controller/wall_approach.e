note
	description: "Exercise 2's reference solution (exercises/2_controller): drive to the wall and stop."

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
		local
			timer: TIMER
		do
			create timer.make
			await_sensors (range)
			from until is_done loop
				step (range, drive)
				if not is_done then
					timer.sleep (Period)
				end
			end
		ensure
			done: is_done
		end

feature {NONE} -- Implementation

	await_sensors (a_range: separate RANGE_SIGNALER)
			-- Return once the range sensors have reported (the wait condition).
		require
			ready: not a_range.is_stale
		do
		end

	step (a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Drive on at `Speed' while the way is clear; stop and be done when it is not.
		do
			if a_range.has_obstacle then
				a_drive.stop
				is_done := True
			else
				a_drive.send (Speed, 0.0)
			end
		end

end
