note
	description: "[
		The controller of the latency benchmark (benchmarks/robots_latency.py): odometry arrives
		on /latency/odom (subscriber -> ODOMETRY_SIGNALER), a LATENCY_CONTROLLER on its own
		processor waits for each new reading and answers on /latency/cmd_vel with a Twist whose
		linear.x is the reading's x (the sequence number of the measuring side). A negative x ends
		the program.
	]"

class
	ROBOTS_LATENCY

create
	make

feature {NONE} -- Initialization

	make
			-- Connect the signaler and the controller, then serve until a negative x arrives.
		local
			odometry: separate ODOMETRY_SIGNALER
			controller: separate LATENCY_CONTROLLER
		do
			create odometry.make ("/latency/odom")
			create controller.make (odometry, "/latency/cmd_vel")
			serve (controller)
			await_end (controller)
			close (odometry)
		end

feature {NONE} -- Implementation

	serve (a_controller: separate LATENCY_CONTROLLER)
			-- Start `a_controller' (an asynchronous call: its own processor runs it).
		do
			a_controller.run
		end

	await_end (a_controller: separate LATENCY_CONTROLLER)
			-- Wait until `a_controller' has answered a negative x.
		require
			finished: a_controller.is_finished
		do
		end

	close (a_odometry: separate ODOMETRY_SIGNALER)
			-- Stop listening.
		do
			a_odometry.close
		end

end
