class
	GENERIC_PUBLISH

create
	make

feature

	make
			-- Publish a Twist, a Float64 and a LaserScan built as Eiffel message objects.
		local
			twist: GEOMETRY_MSGS_TWIST
			number: STD_MSGS_FLOAT64
			scan: SENSOR_MSGS_LASER_SCAN
			p: ROS_PUBLISHER [ROS_MESSAGE]
			remote: separate ROS_PUBLISHER [STD_MSGS_FLOAT64]
		do
			create twist.make
			twist.linear.set_x (0.25)
			twist.angular.set_z (-1.5)
			create p.make ("/cmd_vel")
			p.publish (twist)
			create number.make
			number.set_data (2.5)
			create remote.make ("/number")
			send (remote, number)
			create scan.make
			scan.header.set_frame_id ("laser")
			scan.set_ranges (<<{REAL_32} 0.5, {REAL_32} 1.25>>)
			scan.set_range_max ({REAL_32} 2.0)
			p.publish (scan)
			print (twist.ros_type + " " + p.published_count.out + "%N")
		end

	send (a_publisher: separate ROS_PUBLISHER [STD_MSGS_FLOAT64]; a_message: STD_MSGS_FLOAT64)
		do
			a_publisher.publish (a_message)
		end

end
