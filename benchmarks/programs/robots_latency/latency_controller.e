note
	description: "[
		Answers every new reading of an odometry signaler with one velocity command that echoes
		the reading's x, until a reading with a negative x (echoed too) ends `run'.
	]"

class
	LATENCY_CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_odometry: separate ODOMETRY_SIGNALER; a_topic: separate STRING)
			-- Controller reading `a_odometry' and publishing on `a_topic'.
		do
			odometry := a_odometry
			create publisher.make (a_topic)
		ensure
			odometry_set: odometry = a_odometry
		end

feature -- Access

	odometry: separate ODOMETRY_SIGNALER
			-- Where readings come from.

	publisher: ROS_PUBLISHER [GEOMETRY_MSGS_TWIST]
			-- Where commands go.

	handled: INTEGER
			-- Readings answered so far (the signaler's `update_count' when last answered).

	is_finished: BOOLEAN
			-- Has a negative x been answered?

feature -- Basic operations

	run
			-- Answer readings until a negative x.
		do
			from
			until
				is_finished
			loop
				respond (odometry)
			end
		ensure
			finished: is_finished
		end

feature {NONE} -- Implementation

	respond (a_odometry: separate ODOMETRY_SIGNALER)
			-- Echo the newest reading's x as linear.x.
		require
			new_reading: a_odometry.update_count > handled
		do
			handled := a_odometry.update_count
			publisher.publish_velocity (a_odometry.x, 0.0)
			is_finished := a_odometry.x < 0.0
		ensure
			caught_up: handled = old a_odometry.update_count
		end

end
