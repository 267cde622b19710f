class
	NAV_STOP

create
	make

feature

	make
			-- Start TangentBug, stop it after 3 simulated seconds, report a second later.
		local
			env: ROBOT_ENVIRONMENT
			bug: TANGENT_BUG_BEHAVIOR
			timer: TIMER
		do
			create env
			create timer.make
			create bug.make_for_namespace (env.namespace, env.goal_x, env.goal_y, env.max_linear, env.max_angular)
			bug.start
			timer.sleep (3.0)
			print ("stopping at " + (timer.now * 1000.0).rounded.out + " ms%N")
			bug.stop
			bug.wait_until_finished
			timer.sleep (1.0)
			report (bug.status)
		end

	report (a_status: separate NAVIGATION_SIGNALER)
			-- Print the outcome.
		do
			print (create {STRING}.make_from_separate (a_status.mode_name) + "%N")
		end

end
