note
	description: "[
		The tutorial's first controller (docs/tutorial.md). The Thymio drives forward until
		something is in front, stops, waits until its odometry says it is at rest, turns left
		until the way is clear (and a little more), and does it all three times. Routines with separate arguments
		reserve their processors for their whole body; a precondition on a separate argument is
		a wait condition: the call waits until it holds.
	]"

class
	FIRST_CONTROLLER

create
	make

feature {NONE} -- Initialization

	make
			-- Drive to an obstacle and turn away from it, three times.
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			timer: TIMER
			i, j: INTEGER
		do
			create env
			create robot.make (env.namespace)
			create timer.make
			await_sensors (robot.range_signaler, robot.odometry)
			from i := 1 until i > 3 loop
				from until not cruise (robot.range_signaler, robot.drive) loop
					timer.sleep (Period)
				end
				report_when_still (robot.odometry, i)
				from until not turn (robot.range_signaler, robot.drive) loop
					timer.sleep (Period)
				end
				from j := 1 until j > 6 loop
					turn_on (robot.drive)
					timer.sleep (Period)
					j := j + 1
				end
				i := i + 1
			end
			stop (robot.drive)
			print ("Done after " + timer.elapsed.rounded.out + " s%N")
		end

feature {NONE} -- Control

	Speed: REAL_64 = 0.1
			-- Forward speed (m/s).

	Turn_rate: REAL_64 = 1.5
			-- Turn rate (rad/s).

	Period: REAL_64 = 0.1
			-- Seconds between two commands: 10 Hz, well inside the robot's 0.5 s watchdog.

	await_sensors (range: separate RANGE_SIGNALER; odometry: separate ODOMETRY_SIGNALER)
			-- Wait until both sensors have reported (the wait conditions).
		require
			range_ready: not range.is_stale
			odometry_ready: not odometry.is_stale
		do
		end

	cruise (range: separate RANGE_SIGNALER; drive: separate DIFFERENTIAL_DRIVE): BOOLEAN
			-- Is the way clear? Drive on if it is, stop if it is not.
		do
			Result := not range.has_obstacle
			if Result then
				drive.send (Speed, 0.0)
			else
				drive.stop
			end
		end

	turn (range: separate RANGE_SIGNALER; drive: separate DIFFERENTIAL_DRIVE): BOOLEAN
			-- Is something still in front? Turn left if it is, stop if it is not.
		do
			Result := range.has_obstacle
			if Result then
				drive.send (0.0, Turn_rate)
			else
				drive.stop
			end
		end

	turn_on (drive: separate DIFFERENTIAL_DRIVE)
			-- Keep turning left (past the edge of the obstacle).
		do
			drive.send (0.0, Turn_rate)
		end

	report_when_still (odometry: separate ODOMETRY_SIGNALER; n: INTEGER)
			-- Say where the robot came to rest, once it has (the wait condition).
		require
			at_rest: not odometry.is_moving
		do
			print ("Stop " + n.out + " at x = " + centimetres (odometry.x) + ", y = " + centimetres (odometry.y) + "%N")
		end

	stop (drive: separate DIFFERENTIAL_DRIVE)
			-- Stop the robot.
		do
			drive.stop
		end

	centimetres (metres: REAL_64): STRING
			-- `metres' rounded to the centimetre, with its unit.
		do
			Result := (metres * 100).rounded.out + " cm"
		end

end
