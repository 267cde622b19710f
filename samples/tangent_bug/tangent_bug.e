note
	description: "[
		TangentBug on the simulator: the diff-drive robot of the world goes to the world's goal
		(or `--goal X,Y') among obstacles it discovers with its 2 m laser, and says whether it
		reached the goal or found it unreachable.
	]"

class
	TANGENT_BUG

create
	make

feature {NONE} -- Initialization

	make
			-- Run TangentBug to the goal and report the outcome.
		local
			env: ROBOT_ENVIRONMENT
			robot: separate DIFF_DRIVE_ROBOT
			bug: TANGENT_BUG_BEHAVIOR
		do
			create env
			if env.has_goal then
				print ("tangent bug: going to (" + metres (env.goal_x) + ", " + metres (env.goal_y) + ")%N")
				create robot.make_with_limits (env.namespace, env.max_linear, env.max_angular, False)
				create bug.make_for_robot (robot, env.goal_x, env.goal_y)
				bug.start
				bug.wait_until_finished
				report (bug.status)
			else
				print ("tangent bug: the world has no goal (give one with --goal X,Y)%N")
			end
		end

feature {NONE} -- Implementation

	report (a_status: separate NAVIGATION_SIGNALER)
			-- Print the outcome.
		do
			print ("tangent bug: " + create {STRING}.make_from_separate (a_status.mode_name)
				+ " after " + metres (a_status.path_length) + " m, "
				+ a_status.boundary_count.out + " boundary following(s), "
				+ a_status.leave_count.out + " leave(s)%N")
		end

	metres (v: REAL_64): STRING
			-- `v' with two decimals.
		local
			cm: INTEGER
		do
			cm := (v * 100.0).rounded
			Result := (cm // 100).out + "." + ((cm \\ 100) // 10).out + (cm \\ 10).out
		end

end
