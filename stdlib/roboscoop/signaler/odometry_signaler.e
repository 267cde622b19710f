note
	description: "[
		The robot's odometry (nav_msgs/Odometry on a topic), updated by the transport through
		asynchronous calls on this signaler's processor. Read it in wait conditions.
	]"

class
	ODOMETRY_SIGNALER

inherit
	ODOMETRY_LISTENER

create
	make, make_unconnected

feature {NONE} -- Initialization

	make (a_topic: separate STRING)
			-- Signaler fed by the odometry published on `a_topic' ("/odom", "/robot1/odom").
		do
			make_unconnected
			create subscriber.make (a_topic)
			subscriber.listen_odometry (Current)
		end

	make_unconnected
			-- Signaler fed only by calls of `on_odometry'.
		do
			create clock.make
			moving_threshold := 0.01
			twisting_threshold := 0.01
		end

feature -- Access

	x, y, theta: REAL_64
			-- Last pose: position (m) and heading (rad).

	vx, vtheta: REAL_64
			-- Last forward (m/s) and angular (rad/s) speeds.

	timestamp: REAL_64
			-- Stamp of the last message (s).

	received_at: REAL_64
			-- Runtime clock (s) when the last reading arrived.

	update_count: INTEGER
			-- Readings received.

	pose: POSE_2D
			-- Last pose.
		do
			create Result.make (x, y, theta)
		end

	position: POINT_2D
			-- Last position.
		do
			create Result.make (x, y)
		end

	moving_threshold, twisting_threshold: REAL_64
			-- Speeds below which the robot counts as still.

	subscriber: detachable ROS_SUBSCRIBER
			-- Where readings come from (Void: unconnected).

feature -- Status report

	is_moving: BOOLEAN
			-- Is the robot moving forward or backward?
		do
			Result := vx.abs > moving_threshold
		end

	is_twisting: BOOLEAN
			-- Is the robot turning?
		do
			Result := vtheta.abs > twisting_threshold
		end

	has_reading: BOOLEAN
			-- Has any reading arrived?
		do
			Result := update_count > 0
		end

	is_stale (a_max_age: REAL_64): BOOLEAN
			-- Is there no reading younger than `a_max_age' seconds?
		do
			Result := update_count = 0 or else clock.now - received_at > a_max_age
		end

feature -- Element change

	on_odometry (a_x, a_y, a_theta, a_vx, a_vtheta, a_timestamp: REAL_64)
			-- <Precursor>
		do
			x := a_x
			y := a_y
			theta := a_theta
			vx := a_vx
			vtheta := a_vtheta
			timestamp := a_timestamp
			received_at := clock.now
			update_count := update_count + 1
		ensure then
			counted: update_count = old update_count + 1
		end

	set_thresholds (a_moving, a_twisting: REAL_64)
			-- Set `moving_threshold' and `twisting_threshold'.
		require
			non_negative: a_moving >= 0.0 and a_twisting >= 0.0
		do
			moving_threshold := a_moving
			twisting_threshold := a_twisting
		end

	close
			-- Stop listening.
		do
			if attached subscriber as s then
				s.close
			end
		end

feature {NONE} -- Implementation

	clock: TIMER
			-- The runtime's clock.

end
