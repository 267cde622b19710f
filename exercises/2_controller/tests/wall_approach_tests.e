note
	description: "[
		The grading tests of exercise 2 (README.md), in the corridor of world.yaml: the robot
		drives to the wall across it and stops in front of it without touching it.
	]"

class
	WALL_APPROACH_TESTS

inherit
	ROBOT_TEST_SET

feature -- Tests

	test_stops_in_front_of_the_wall
			-- Forty simulated seconds: at the wall, no collision, at rest, done.
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			controller: separate WALL_APPROACH
		do
			create env
			create robot.make (env.namespace)
			create controller.make (robot.range_signaler, robot.drive)
			go (controller)
			run_for (40.0)
			assert_no_collision ("no collision")
			assert_at_position ("in front of the wall", 1.85, 0.5, 0.1)
			assert ("at rest for the last 10 s", last_moved_at < simulated_time - 10.0)
			assert ("done", is_done (controller))
		end

	test_drives_straight
			-- Five simulated seconds: on its way along the corridor's middle. (Asking the
			-- controller whether it is done would wait until `run' is over: its processor is busy.)
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			controller: separate WALL_APPROACH
		do
			create env
			create robot.make (env.namespace)
			create controller.make (robot.range_signaler, robot.drive)
			go (controller)
			run_for (5.0)
			assert_reals_equal ("along the middle", 0.5, robot_y, 0.01)
			assert_distance_driven ("about 0.1 m/s", 0.35, 0.55)
		end

feature {NONE} -- Implementation

	go (c: separate WALL_APPROACH)
		do
			c.run
		end

	is_done (c: separate WALL_APPROACH): BOOLEAN
		do
			Result := c.is_done
		end

end
