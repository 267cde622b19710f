note
	description: "[
		Velocity commands of a differential-drive robot (geometry_msgs/Twist on its cmd_vel
		topic), clamped to linear and angular limits.
	]"

class
	DIFFERENTIAL_DRIVE

create
	make, make_stamped

feature {NONE} -- Initialization

	make (a_topic: separate STRING; a_max_linear, a_max_angular: REAL_64)
			-- Drive publishing Twist on `a_topic', at most `a_max_linear' m/s and `a_max_angular' rad/s.
		require
			positive_limits: a_max_linear > 0.0 and a_max_angular > 0.0
		do
			create publisher.make (a_topic)
			max_linear := a_max_linear
			max_angular := a_max_angular
		end

	make_stamped (a_topic: separate STRING; a_max_linear, a_max_angular: REAL_64)
			-- Like `make', with TwistStamped commands.
		require
			positive_limits: a_max_linear > 0.0 and a_max_angular > 0.0
		do
			create publisher.make_stamped (a_topic)
			max_linear := a_max_linear
			max_angular := a_max_angular
		end

feature -- Access

	max_linear, max_angular: REAL_64
			-- Speed limits (m/s, rad/s).

	linear, angular: REAL_64
			-- Last command sent.

	command_count: INTEGER
			-- Commands sent.
		do
			Result := publisher.published_count
		end

feature -- Status report

	is_stopped: BOOLEAN
			-- Was the last command a zero velocity?
		do
			Result := linear = 0.0 and angular = 0.0
		end

feature -- Basic operations

	send (v, w: REAL_64)
			-- Command forward speed `v' and turn rate `w', clamped to the limits.
		do
			linear := v.max (- max_linear).min (max_linear)
			angular := w.max (- max_angular).min (max_angular)
			publisher.publish_velocity (linear, angular)
		ensure
			linear_limited: linear.abs <= max_linear
			angular_limited: angular.abs <= max_angular
			counted: command_count = old command_count + 1
		end

	stop
			-- Command a zero velocity.
		do
			send (0.0, 0.0)
		ensure
			stopped: is_stopped
		end

feature {NONE} -- Implementation

	publisher: ROS_PUBLISHER [ROS_MESSAGE]
			-- Where commands go (Twist or TwistStamped, by `publish_velocity').

end
