note
	description: "[
		Robot tests of WANDER_BEHAVIOR in the wander sample's room (world.yaml beside this
		class): it keeps clear of boxes and the hole, and stops when asked. `test_reaches_corner'
		fails: wandering does not go to a given place.
	]"

class
	WANDER_TESTS

inherit
	ROBOT_TEST_SET

feature -- Tests

	test_wanders_safely
			-- Thirty seconds of wandering, then a stop: no collision, no fall, a stop within a second.
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			wanderer: WANDER_BEHAVIOR
		do
			create env
			create robot.make (env.namespace)
			create wanderer.make_for_robot (robot)
			wanderer.start
			run_for (30.0)
			wanderer.stop
			mark_stop_request
			run_for (2.0)
			assert_no_collision ("no collision")
			assert_never_in_hole ("no fall")
			assert_stopped_within ("stops", 1.0)
			assert_distance_driven ("it moved", 1.0, 10.0)
			assert_battery_left ("battery", 0.5)
			print ("x = " + robot_x.out + ", y = " + robot_y.out + ", heading = " + robot_heading.out + "%N")
		end

	test_reaches_corner
		note
			world: "world.yaml"
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			wanderer: WANDER_BEHAVIOR
		do
			create env
			create robot.make (env.namespace)
			create wanderer.make_for_robot (robot)
			wanderer.start
			run_for (5.0)
			assert_position_reached ("far corner", 2.3, 1.8, 0.1)
		end

end
