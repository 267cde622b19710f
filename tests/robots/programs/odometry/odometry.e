class
	ODOMETRY

create
	make

feature

	make
			-- Wait until the robot is past x = 1, then until the last of a burst arrived.
		local
			odom: separate ODOMETRY_SIGNALER
		do
			create odom.make ("/odom")
			wait_past (odom)
			wait_last (odom)
		end

	wait_past (odom: separate ODOMETRY_SIGNALER)
			-- Report the first reading past x = 1.
		require
			odom.x > 1.0
		do
			print ("past " + odom.x.out + " moving " + odom.is_moving.out + "%N")
		end

	wait_last (odom: separate ODOMETRY_SIGNALER)
			-- Report once the reading with x = 1000 arrived.
		require
			odom.x >= 1000.0
		do
			print ("last " + odom.x.out + " theta " + odom.theta.out + " updates " + odom.update_count.out + "%N")
			odom.close
		end

end
