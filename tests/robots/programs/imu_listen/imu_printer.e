class
	IMU_PRINTER

inherit
	ROS_LISTENER [SENSOR_MSGS_IMU]

create
	make

feature

	make
			-- Listen to /imu.
		do
			create subscriber.make ("/imu")
			subscriber.listen (Current)
		end

	subscriber: ROS_SUBSCRIBER [SENSOR_MSGS_IMU]
			-- The subscription.

	has_message: BOOLEAN
			-- Did a message come?

	acceleration_z, orientation_w: REAL_64
			-- Values of the last message.

	on_message (a_message: SENSOR_MSGS_IMU)
			-- <Precursor>
		do
			has_message := True
			acceleration_z := a_message.linear_acceleration.z
			orientation_w := a_message.orientation.w
		end

	close
			-- Stop listening.
		do
			subscriber.close
		end

end
