note
	description: "[
		Subscribes to one topic of the robot's transport, whose messages are of type `M', on
		behalf of a listener in the same region. Each incoming message becomes an asynchronous
		call on the listener's processor: `on_message' of a ROS_LISTENER [M] with the message as
		an Eiffel object (`listen'), or, for the signalers' common messages, an `on_...' routine
		with plain values (`listen_odometry', `listen_range', ...). Messages are coalesced: a slow
		listener gets the newest one, no queue grows.
	]"

class
	ROS_SUBSCRIBER [M -> ROS_MESSAGE]

create
	make

feature {NONE} -- Initialization

	make (a_topic: separate STRING)
			-- Subscriber on `a_topic' (a full name: "/odom", "/robot1/odom").
		do
			create topic.make_from_separate (a_topic)
		end

feature -- Access

	topic: STRING
			-- Full topic name.

	received_count: INTEGER
			-- Messages seen on the transport so far.
		external
			"Python"
		end

	logged_count: INTEGER
			-- Calls logged on listeners so far (at most one per message; fewer when coalesced).
		external
			"Python"
		end

feature -- Basic operations

	listen (a_listener: ROS_LISTENER [M])
			-- Deliver every message to `a_listener''s `on_message', as a new object of `M' in its region.
		external
			"Python"
		end

	listen_odometry (a_listener: ODOMETRY_LISTENER)
			-- Deliver nav_msgs/Odometry messages to `a_listener'.
		external
			"Python"
		end

	listen_range (a_listener: RANGE_LISTENER; a_sensor: INTEGER)
			-- Deliver sensor_msgs/Range messages to `a_listener' as readings of `a_sensor'.
		external
			"Python"
		end

	listen_scan (a_listener: SCAN_LISTENER)
			-- Deliver sensor_msgs/LaserScan messages to `a_listener' (ranges as a fresh ARRAY [REAL_64]
			-- on its processor, indexed from 1).
		external
			"Python"
		end

	listen_battery (a_listener: BATTERY_LISTENER)
			-- Deliver sensor_msgs/BatteryState messages to `a_listener'.
		external
			"Python"
		end

	close
			-- Stop every delivery of this subscriber.
		external
			"Python"
		end

end
