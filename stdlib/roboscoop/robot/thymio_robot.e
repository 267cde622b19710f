note
	description: "[
		A Thymio II under a topic namespace, with the topics of its ROS 2 driver: cmd_vel, odom,
		battery_state, the seven proximity sensors proximity/{left, center_left, center,
		center_right, right, rear_left, rear_right} and the two ground sensors ground/{left,
		right} (sensor_msgs/Range). `range_signaler' sees all nine (obstacles in front, holes
		under the ground sensors); `proximity' and `ground' are the same sensors as groups
		(GROUP_SIGNALER), made on first use. Default speed limits: 0.14 m/s, 3 rad/s.
	]"

class
	THYMIO_ROBOT

inherit
	DIFF_DRIVE_ROBOT
		redefine
			make_range_signaler, default_max_linear, default_max_angular
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
