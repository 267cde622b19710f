note
	description: "[
		Drives the robot about a room: straight ahead while the way is clear, turning left
		while something is in front, until its STOP_SIGNALER says stop (exercise 3, README.md).
		Given complete: each step reserves the stop signaler, the range signaler and the drive,
		so no command is sent once the stop is seen.
	]"

class
	PATROL_CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_stop: separate STOP_SIGNALER; a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- A controller stopped by `a_stop', reading `a_range', commanding `a_drive'.
		do
			stop_signaler := a_stop
			range := a_range
			drive := a_drive
		end

feature -- Access

	stop_signaler: separate STOP_SIGNALER
			-- Says when to stop.

	range: separate RANGE_SIGNALER
			-- What is around the robot.

	drive: separate DIFFERENTIAL_DRIVE
			-- Its wheels.

	Speed: REAL_64 = 0.1
			-- Forward speed (m/s).

	Turn_rate: REAL_64 = 1.5
			-- Turn rate (rad/s).

	Period: REAL_64 = 0.1
			-- Seconds between two steps.

feature -- Basic operations

	run
			-- Step every `Period' seconds until the stop.
		local
			timer: TIMER
			going: BOOLEAN
		do
			create timer.make
			from going := True until not going loop
				going := step (stop_signaler, range, drive)
				if going then
					timer.sleep (Period)
				end
			end
		end

feature {NONE} -- Implementation

	step (a_stop: separate STOP_SIGNALER; a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE): BOOLEAN
			-- Stop the robot if a stop is requested (False: the end); else drive or turn (True).
		require
			sensors_ready: a_stop.is_stop_requested or not a_range.is_stale
		do
			if a_stop.is_stop_requested then
				a_drive.stop
			elseif a_range.has_obstacle then
				a_drive.send (0.0, Turn_rate)
				Result := True
			else
				a_drive.send (Speed, 0.0)
				Result := True
			end
		end

end
