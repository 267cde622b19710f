note
	description: "[
		A Thymio II under a topic namespace, with the topics of its ROS 2 driver (jeguzzi/ros-thymio,
		thymio_driver/thymio_driver/base.py and thymio_driver_node.py): cmd_vel (Twist, whatever
		the distribution), odom, the seven proximity sensors proximity/{left, center_left, center,
		center_right, right, rear_left, rear_right} and the two ground sensors ground/{left,
		right} (sensor_msgs/Range). The driver's conventions: a proximity sensor reads -1 when it
		sees nothing and its min_range when saturated; a ground sensor reads 0 over the floor and 1
		(beyond its max_range) where nothing reflects. `range_signaler' sees all nine (obstacles in
		front, holes under the ground sensors); `proximity' and `ground' are the same sensors as
		groups (GROUP_SIGNALER), made on first use. The driver publishes no battery state: on a
		ROS 2 robot `battery' says so once and stays full (the simulator's Thymio has one).
		Default speed limits: 0.14 m/s, 3 rad/s.
	]"

class
	THYMIO_ROBOT

inherit
	DIFF_DRIVE_ROBOT
		redefine
			make_range_signaler, default_max_linear, default_max_angular, battery
		end

create
	make, make_stamped, make_with_limits

feature -- Access

	default_max_linear: REAL_64
			-- <Precursor>
		do
			Result := 0.14
		end

	default_max_angular: REAL_64
			-- <Precursor>
		do
			Result := 3.0
		end

	battery: separate BATTERY_SIGNALER
			-- <Precursor>
			-- On a ROS 2 robot: missing (the Thymio driver publishes no battery state).
		local
			env: ROBOT_ENVIRONMENT
		once ("OBJECT")
			create env
			if env.is_ros2 then
				create Result.make_missing (topic ("battery_state"), "the ROS 2 Thymio driver publishes none")
			else
				create Result.make (topic ("battery_state"))
			end
		end

	proximity: separate GROUP_SIGNALER
			-- The seven proximity sensors as a group (0 left .. 4 right, 5 rear_left, 6 rear_right).
		once ("OBJECT")
			create Result.make_thymio_proximity (namespace)
		end

	ground: separate GROUP_SIGNALER
			-- The two ground sensors as a group (0 left, 1 right).
		once ("OBJECT")
			create Result.make_thymio_ground (namespace)
		end

feature {NONE} -- Implementation

	make_range_signaler
			-- Create `range_signaler' from the proximity and ground sensors.
		do
			create range_signaler.make_thymio (namespace)
		end

end
