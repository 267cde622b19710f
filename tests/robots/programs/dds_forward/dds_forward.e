note
	description: "[
		Drives the robot of /robot1 forward at 0.1 m/s for two seconds of the runtime's clock, then
		stops it, once its odometry has arrived (so the simulator node is up). Prints where the
		robot was when it started and where the odometry said it was at the end.
	]"

class
	DDS_FORWARD

create
	make

feature {NONE} -- Initialization

	make
			-- Wait for odometry, drive forward, stop, report.
		local
			odometry: separate ODOMETRY_SIGNALER
			drive: separate DIFFERENTIAL_DRIVE
			i: INTEGER
		do
			create odometry.make ("/robot1/odom")
			create drive.make ("/robot1/cmd_vel", 0.14, 3.0)
			report ("start", odometry)
			from
				i := 1
			until
				i > 40
			loop
				send (drive, 0.1)
				(create {EXECUTION_ENVIRONMENT}).sleep (50_000_000)
				i := i + 1
			end
			send (drive, 0.0)
			(create {EXECUTION_ENVIRONMENT}).sleep (500_000_000)
			report ("end", odometry)
			close (odometry)
		end

feature {NONE} -- Implementation

	send (a_drive: separate DIFFERENTIAL_DRIVE; a_speed: REAL_64)
			-- Command `a_speed' forward, no turn.
		do
			a_drive.send (a_speed, 0.0)
		end

	report (a_label: STRING; a_odometry: separate ODOMETRY_SIGNALER)
			-- Print `a_label' and the last pose, once a reading has arrived.
		require
			has_reading: a_odometry.has_reading
		do
			print (a_label + " " + a_odometry.x.out + " " + a_odometry.y.out + "%N")
		end

	close (a_odometry: separate ODOMETRY_SIGNALER)
			-- Stop listening.
		do
			a_odometry.close
		end

end
