class
	SENSORS_APP

create
	make

feature

	make
			-- A Thymio facing a wall and a laser robot facing a box: what their signalers see.
		local
			env: ROBOT_ENVIRONMENT
			thymio: THYMIO_ROBOT
			laser_robot: DIFF_DRIVE_ROBOT
		do
			create env
			create thymio.make (env.namespace_of (1))
			create laser_robot.make (env.namespace_of (2))
			print ("namespaces " + thymio.namespace + " " + laser_robot.namespace + " " + thymio.topic ("odom") + "%N")
			show_thymio (thymio.range_signaler, thymio.proximity, thymio.ground)
			show_laser (laser_robot.range_signaler)
		end

	show_thymio (r: separate RANGE_SIGNALER; p, g: separate GROUP_SIGNALER)
		require
			not r.is_stale
			not p.is_stale
			not g.is_stale
		do
			print ("thymio: obstacle " + r.has_obstacle.out + " left " + r.is_obstacle_left.out + " right "
				+ r.is_obstacle_right.out + " hole " + r.has_ground_hole.out + " proximity sensors "
				+ p.sensor_count.out + " nearest sensor " + p.nearest_sensor.out + " at " + ((p.nearest * 1000.0).rounded).out
				+ " mm, ground " + g.sensor_count.out + " nearest " + ((g.nearest * 1000.0).rounded).out + " mm%N")
		end

	show_laser (r: separate RANGE_SIGNALER)
		require
			r.scan_count > 0
		do
			print ("laser: obstacle " + r.has_obstacle.out + " left " + r.is_obstacle_left.out + " right "
				+ r.is_obstacle_right.out + " behind " + r.is_obstacle_behind.out + " front at "
				+ ((r.nearest_front * 100.0).rounded).out + " cm, stale " + r.is_stale.out + "%N")
		end

end
