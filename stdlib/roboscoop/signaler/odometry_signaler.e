note
	description: "[
		The robot's odometry (nav_msgs/Odometry on a topic), updated by the transport through
		asynchronous calls on this signaler's processor. Read it in wait conditions. Reports
		stale data (`is_stale') when the topic goes silent.
	]"

class
	ODOMETRY_SIGNALER

inherit
	ODOMETRY_LISTENER

	SENSOR_SIGNALER

create
	make, make_unconnected

feature {NONE} -- Initialization

	make (a_topic: separate STRING)
			-- Signaler fed by the odometry published on `a_topic' ("/odom", "/robot1/odom").
		do
			make_unconnected
			new_subscriber (create {STRING}.make_from_separate (a_topic)).listen_odometry (Current)
		end

	make_unconnected
			-- Signaler fed only by calls of `on_odometry'.
		do
			make_sensor
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

feature -- Status report

	is_moving: BOOLEAN
			-- Is the robot moving: forward, backward or turning (in place too)?
		do
			Result := vx.abs > moving_threshold or is_twisting
		end

	is_twisting: BOOLEAN
			-- Is the robot turning?
		do
			Result := vtheta.abs > twisting_threshold
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
			note_reading
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

end
