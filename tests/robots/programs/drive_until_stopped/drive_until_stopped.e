note
	description: "[
		Drives forward at 0.1 m/s until the run is stopped from outside (a signal). Prints
		`moving' once the odometry shows the robot has moved 2 cm, so a test knows that velocity
		commands have reached the robot before it sends the signal.
	]"

class
	DRIVE_UNTIL_STOPPED

create
	make

feature {NONE} -- Initialization

	make
			-- Drive on; say `moving' once.
		local
			env: ROBOT_ENVIRONMENT
			odometry: separate ODOMETRY_SIGNALER
			drive: separate DIFFERENTIAL_DRIVE
			start: REAL_64
			told: BOOLEAN
		do
			create env
			create odometry.make (env.namespace + "/odom")
			create drive.make (env.namespace + "/cmd_vel", env.max_linear, env.max_angular)
			start := first_x (odometry)
			from
			until
				False
			loop
				send (drive)
				if not told and then x_of (odometry) > start + 0.02 then
					print ("moving%N")
					told := True
				end
				(create {EXECUTION_ENVIRONMENT}).sleep (50_000_000)
			end
		end

feature {NONE} -- Implementation

	first_x (a_odometry: separate ODOMETRY_SIGNALER): REAL_64
			-- The first reading's x, once there is one.
		require
			has_reading: a_odometry.has_reading
		do
			Result := a_odometry.x
		end

	x_of (a_odometry: separate ODOMETRY_SIGNALER): REAL_64
			-- The last reading's x.
		do
			Result := a_odometry.x
		end

	send (a_drive: separate DIFFERENTIAL_DRIVE)
			-- Forward at 0.1 m/s.
		do
			a_drive.send (0.1, 0.0)
		end

end
