note
	description: "Waits until the robot is far enough from where it started, then requests the stop."

class
	SUPERVISOR

create
	make

feature {NONE} -- Initialization

	make (a_stop: separate STOP_SIGNALER; a_odometry: separate ODOMETRY_SIGNALER; a_distance: REAL_64)
			-- Supervisor stopping `a_stop' once `a_odometry' is `a_distance' m from its first reading.
		require
			positive_distance: a_distance > 0.0
		do
			stop := a_stop
			odometry := a_odometry
			distance := a_distance
		end

feature -- Access

	stop: separate STOP_SIGNALER
			-- What to raise.

	odometry: separate ODOMETRY_SIGNALER
			-- Where the robot is.

	distance: REAL_64
			-- How far the robot may go (m).

	start_x, start_y: REAL_64
			-- First position seen.

feature -- Basic operations

	supervise
			-- Note the start, wait until the robot is `distance' away, request the stop.
		do
			note_start (odometry)
			await_far (odometry, stop)
		end

feature {NONE} -- Implementation

	note_start (a_odometry: separate ODOMETRY_SIGNALER)
			-- Remember the first position.
		require
			a_odometry.has_reading
		do
			start_x := a_odometry.x
			start_y := a_odometry.y
		end

	await_far (a_odometry: separate ODOMETRY_SIGNALER; a_stop: separate STOP_SIGNALER)
			-- Request the stop once the robot is `distance' from the start.
		require
			(a_odometry.x - start_x) ^ 2 + (a_odometry.y - start_y) ^ 2 >= distance ^ 2
		do
			a_stop.request_stop
			print ("Supervisor: " + distance.out + " m from the start, stop requested%N")
		end

end
