note
	description: "[
		Publishes messages of type `M' on one topic of the robot's transport: `publish' takes a
		message object (converted to its ROS 2 type on this processor); `publish_velocity' and
		`publish_real' build a Twist (or TwistStamped) and a Float64 from plain values.
	]"

class
	ROS_PUBLISHER [M -> ROS_MESSAGE]

create
	make, make_stamped

feature {NONE} -- Initialization

	make (a_topic: separate STRING)
			-- Publisher on `a_topic' (a full name: "/cmd_vel", "/robot1/cmd_vel").
		do
			create topic.make_from_separate (a_topic)
		ensure
			not_stamped: not is_stamped
		end

	make_stamped (a_topic: separate STRING)
			-- Publisher on `a_topic' whose velocity commands are TwistStamped.
		do
			make (a_topic)
			is_stamped := True
		ensure
			stamped: is_stamped
		end

feature -- Access

	topic: STRING
			-- Full topic name.

	is_stamped: BOOLEAN
			-- Are velocity commands sent as geometry_msgs/TwistStamped?

	published_count: INTEGER
			-- Messages published so far.

feature -- Basic operations

	publish (a_message: separate M)
			-- Publish `a_message' (converted to its ROS 2 type on this processor).
		do
			publish_message (a_message)
			published_count := published_count + 1
		ensure
			counted: published_count = old published_count + 1
		end

	publish_velocity (a_linear, a_angular: REAL_64)
			-- Publish a geometry_msgs/Twist (or TwistStamped) with linear.x = `a_linear'
			-- and angular.z = `a_angular'.
		do
			publish_twist (a_linear, a_angular)
			published_count := published_count + 1
		ensure
			counted: published_count = old published_count + 1
		end

	publish_real (a_value: REAL_64)
			-- Publish a std_msgs/Float64.
		do
			publish_float64 (a_value)
			published_count := published_count + 1
		ensure
			counted: published_count = old published_count + 1
		end

feature {NONE} -- Transport

	publish_message (a_message: separate ROS_MESSAGE)
			-- Put `a_message' on the transport.
		external
			"Python"
		end

	publish_twist (a_linear_x, a_angular_z: REAL_64)
			-- Put the Twist on the transport.
		external
			"Python"
		end

	publish_float64 (a_value: REAL_64)
			-- Put the Float64 on the transport.
		external
			"Python"
		end

end
