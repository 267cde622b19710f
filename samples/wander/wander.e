note
	description: "[
		Wandering: a Thymio meanders around a room with boxes: it drives straight, swerves at
		random every few seconds, and gets away from obstacles and holes (WANDER_BEHAVIOR).
		After two minutes the program stops the behaviour and the robot comes to rest.
	]"

class
	WANDER

create
	make

feature {NONE} -- Initialization

	make
			-- Wander for `Wander_time' seconds, then stop.
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			wanderer: WANDER_BEHAVIOR
			clock: TIMER
		do
			create env
			create clock.make
			create robot.make (env.namespace)
			create wanderer.make_for_robot (robot)
			wanderer.start
			print ("Wandering with " + robot.namespace + "%N")
			clock.sleep (Wander_time)
			wanderer.stop
			print ("Stopped after " + clock.elapsed.out + " s%N")
		end

	Wander_time: REAL_64 = 120.0
			-- Seconds of wandering.

end
