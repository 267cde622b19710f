note
	description: "[
		The grading test of exercise 5 (README.md), in the world of world.yaml: tangent bug with
		TUNING's parameters reaches the goal behind the wall, through the gap, within 35
		simulated seconds, driving at most 9 m, without collision.
	]"

class
	TANGENT_BUG_TESTS

inherit
	ROBOT_TEST_SET

feature -- Tests

	test_reaches_the_goal_quickly
			-- Run until tangent bug is finished, or 35 s have passed.
		local
			env: ROBOT_ENVIRONMENT
			tuning: TUNING
			bug: TANGENT_BUG_BEHAVIOR
		do
			create env
			create tuning
			create bug.make_for_namespace (env.namespace, env.goal_x, env.goal_y, tuning.Linear_speed, tuning.Angular_speed)
			bug.set_robot_radius (tuning.Robot_radius)
			bug.start
			from until bug.is_finished or simulated_time >= 35.0 loop
				run_for (1.0)
			end
			assert ("finished within 35 s", bug.is_finished)
			assert ("the goal was found reachable", bug.is_goal_reached)
			assert_position_reached ("at the goal", env.goal_x, env.goal_y, 0.2)
			assert_no_collision ("no collision")
			assert_distance_driven ("a short path", 0.0, 9.0)
		end

end
