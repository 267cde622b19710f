note
	description: "[
		A mobile robot as the Roboscoop paper speaks to it: drive at the default speed, turn left
		or right, stop, go to the charging station. A controller holds a `separate ROBOT' and calls
		these commands in the body of a guarded routine (the paper's `go', `turn' and `stop' of
		SIMPLE_CONTROLLER, its `go_charging'). DIFF_DRIVE_ROBOT effects them with its drive, its
		range signaler and its odometry; THYMIO_ROBOT and TURTLEBOT3_ROBOT inherit them.
	]"

deferred class
	ROBOT

feature -- Basic operations

	apply_default_speed
			-- Drive straight ahead at the robot's default speed.
		deferred
		end

	turn_left
			-- Turn in place to the left until the front is clear, then stop.
		deferred
		end

	turn_right
			-- Turn in place to the right until the front is clear, then stop.
		deferred
		end

	stop
			-- Stop the robot.
		deferred
		end

	go_to_charging_station
			-- Drive to the charging station and stop there (nothing when there is none).
		deferred
		end

end
