class
	ODOMETRY_PRINTER

inherit
	ROS_LISTENER [NAV_MSGS_ODOMETRY]

create
	make

feature

	make (a_topic: separate STRING)
			-- Listen to `a_topic'.
		do
			create frame.make_empty
			create subscriber.make (a_topic)
			subscriber.listen (Current)
		end

	subscriber: ROS_SUBSCRIBER [NAV_MSGS_ODOMETRY]
			-- The subscription.

	count: INTEGER
			-- Messages delivered.

	last_x: REAL_64
			-- Position x of the last message.

	frame: STRING
			-- Frame of the last message.

	covariance_count: INTEGER
			-- Entries of the last pose covariance.

	on_message (a_message: NAV_MSGS_ODOMETRY)
			-- <Precursor>
		do
			count := count + 1
			last_x := a_message.pose.pose.position.x
			frame := a_message.header.frame_id
			covariance_count := a_message.pose.covariance.count
		end

	close
			-- Stop listening.
		do
			subscriber.close
		end

end
