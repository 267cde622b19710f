note
	description: "[
		The grading tests of exercise 3 (README.md), in the room of world.yaml: the patrol drives
		about without collision, and stops within a second of its own stop or of a stop of its
		parent signaler, through a tree of stop signalers.
	]"

class
	PATROL_BEHAVIOR_TESTS

inherit
	ROBOT_TEST_SET

feature -- Tests

	test_stops_with_its_parent
			-- Twenty seconds of patrol, then a stop of the parent signaler.
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			patrol: PATROL_BEHAVIOR
			parent: separate STOP_SIGNALER
		do
			create env
			create robot.make (env.namespace)
			create parent.make
			create patrol.make (robot.range_signaler, robot.drive)
			patrol.set_parent (parent)
			patrol.start
			run_for (20.0)
			assert_distance_driven ("it patrols", 1.0, 3.0)
			assert_no_collision ("no collision")
			request (parent)
			mark_stop_request
			run_for (3.0)
			assert_stopped_within ("stopped with its parent", 1.0)
			if attached patrol.stop_signaler as s then
				assert_integers_equal ("one child signaler, the controller's", 1, child_count (s))
			end
		end

	test_stops_by_itself
			-- Ten seconds of patrol, then the behaviour's own stop.
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			patrol: PATROL_BEHAVIOR
		do
			create env
			create robot.make (env.namespace)
			create patrol.make (robot.range_signaler, robot.drive)
			patrol.start
			run_for (10.0)
			patrol.stop
			mark_stop_request
			run_for (3.0)
			assert_stopped_within ("stopped", 1.0)
			assert_distance_driven ("it patrolled", 0.5, 1.5)
		end

feature {NONE} -- Implementation

	request (s: separate STOP_SIGNALER)
		do
			s.request_stop
		end

	child_count (s: separate STOP_SIGNALER): INTEGER
		do
			Result := s.child_count
		end

end
