class
	FOREVER

create
	make

feature

	make
			-- Drive forward until x >= 2, then stop.
		local
			env: ROBOT_ENVIRONMENT
			odom: separate ODOMETRY_SIGNALER
			drive: separate DIFFERENTIAL_DRIVE
		do
			create env
			print ("robot " + env.namespace + " of " + env.robot_count.out + " simulated " + env.is_simulated.out + " goal " + env.goal_x.out + "," + env.goal_y.out + "%N")
			create odom.make (env.namespace + "/odom")
			create drive.make (env.namespace + "/cmd_vel", env.max_linear, env.max_angular)
			from until at_x (odom, drive, 200.0) loop
				(create {EXECUTION_ENVIRONMENT}).sleep (100_000_000)
			end
			stop (drive)
			print ("stopped at " + x_of (odom).out + "%N")
		end

	at_x (o: separate ODOMETRY_SIGNALER; d: separate DIFFERENTIAL_DRIVE; limit: REAL_64): BOOLEAN
		do
			Result := o.x >= limit
			if not Result then
				d.send (0.1, 0.0)
			end
		end

	stop (d: separate DIFFERENTIAL_DRIVE)
		do
			d.stop
		end

	x_of (o: separate ODOMETRY_SIGNALER): REAL_64
		do
			Result := o.x
		end

end
