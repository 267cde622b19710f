note
	description: "[
		Go to goal on the simulator: the robot drives to the world's goal (or `--goal X,Y') with
		a PID on its heading and distance, from odometry alone (no obstacle avoidance: use an
		open world), and says when it is there.
	]"

class
	GO_TO_GOAL

create
	make

feature {NONE} -- Initialization

	make
			-- Drive to the goal and report.
		local
			env: ROBOT_ENVIRONMENT
			behavior: GO_TO_GOAL_BEHAVIOR
		do
			create env
			if env.has_goal then
				print ("go to goal: driving to (" + (env.goal_x * 100.0).rounded.out + ", " + (env.goal_y * 100.0).rounded.out + ") cm%N")
				create behavior.make_for_namespace (env.namespace, env.goal_x, env.goal_y, env.max_linear, env.max_angular)
				behavior.start
				behavior.wait_until_finished
				report (behavior.status)
			else
				print ("go to goal: the world has no goal (give one with --goal X,Y)%N")
			end
		end

feature {NONE} -- Implementation

	report (a_status: separate NAVIGATION_SIGNALER)
			-- Print the outcome.
		do
			print ("go to goal: " + create {STRING}.make_from_separate (a_status.mode_name)
				+ ", " + (a_status.distance_to_goal * 100.0).rounded.out + " cm from the goal, after "
				+ (a_status.path_length * 100.0).rounded.out + " cm%N")
		end

end
