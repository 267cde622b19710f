class
	STAMPED_APP

create
	make

feature

	make
			-- Drive a robot that takes TwistStamped commands forward for one second, then stop.
		local
			env: ROBOT_ENVIRONMENT
			robot: DIFF_DRIVE_ROBOT
			clock: TIMER
			i: INTEGER
		do
			create env
			create clock.make
			create robot.make_stamped (env.namespace)
			from i := 1 until i > 10 loop
				send (robot.drive, 0.2)
				clock.sleep (0.1)
				i := i + 1
			end
			send (robot.drive, 0.0)
			print ("stamped " + robot.is_stamped.out + " travelled " + x_of (robot.odometry).out + " cm%N")
		end

	send (d: separate DIFFERENTIAL_DRIVE; v: REAL_64)
		do
			d.send (v, 0.0)
		end

	x_of (o: separate ODOMETRY_SIGNALER): INTEGER
			-- Centimetres travelled along x since the start (x = 1 m), after one second.
		require
			o.timestamp >= 1.0
		do
			Result := ((o.x - 1.0) * 100.0).rounded
		end

end
