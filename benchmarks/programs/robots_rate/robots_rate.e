note
	description: "[
		The program of the controller-rate benchmark (benchmarks/robots_rate.py). Controller_count
		controllers (first argument, default 10) run at once, as fast as they can, for Seconds
		seconds of the runtime's clock each (second argument, default 1.0) after Warmup untimed
		iterations (fourth argument, default 200). An iteration reserves a stop signaler, an
		odometry signaler and a drive, evaluates a wait condition over the signalers and sends
		one velocity command. Third argument `shared': every controller shares one stop signaler
		and one drive (one robot, as the controllers of a behaviour do); anything else: each has
		its own. Every controller prints its timed iteration count and the seconds they took.
	]"

class
	ROBOTS_RATE

inherit
	ARGUMENTS

create
	make

feature {NONE} -- Initialization

	make
			-- Create the signalers, drives and controllers, run them, wait for every one.
		local
			l_count, l_warmup: INTEGER
			l_seconds: REAL_64
			l_shared: BOOLEAN
			l_stop: separate STOP_SIGNALER
			l_drive: separate DIFFERENTIAL_DRIVE
			l_odometry: separate ODOMETRY_SIGNALER
			l_controller: separate RATE_CONTROLLER
			l_controllers: ARRAYED_LIST [separate RATE_CONTROLLER]
		do
			l_count := 10
			l_seconds := 1.0
			l_warmup := 200
			if argument_count >= 1 then
				l_count := argument (1).to_integer
			end
			if argument_count >= 2 then
				l_seconds := argument (2).to_double
			end
			l_shared := argument_count >= 3 and then argument (3) ~ "shared"
			if argument_count >= 4 then
				l_warmup := argument (4).to_integer
			end
			create l_controllers.make (l_count)
			create l_stop.make
			create l_drive.make ("/robot1/cmd_vel", 0.5, 1.0)
			across 1 |..| l_count as i loop
				if not l_shared then
					create l_stop.make
					create l_drive.make ("/robot" + i.item.out + "/cmd_vel", 0.5, 1.0)
				end
				create l_odometry.make_unconnected
				create l_controller.make (i.item, l_stop, l_odometry, l_drive, l_warmup, l_seconds)
				l_controllers.extend (l_controller)
			end
			across l_controllers as c loop
				launch (c.item)
			end
			across l_controllers as c loop
				join (c.item)
			end
		end

feature {NONE} -- Implementation

	launch (a_controller: separate RATE_CONTROLLER)
			-- Start `a_controller' on its own processor.
		do
			a_controller.run
		end

	join (a_controller: separate RATE_CONTROLLER)
			-- Wait until `a_controller' has finished and print its figures.
		require
			finished: a_controller.is_finished
		do
			print ("controller " + a_controller.id.out + " iterations " + a_controller.iteration_count.out
				+ " seconds " + a_controller.seconds.out + "%N")
		end

end
