class
	EXPLORE_STOP_APP

create
	make

feature

	make
			-- Explore for a while (the number of seconds is the first argument, default 20), then
			-- stop the behaviour and say when; watch one more second. With a second argument
			-- "parent", stop a parent STOP_SIGNALER instead of calling the behaviour's `stop'.
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			explorer: EXPLORATION_BEHAVIOR
			master: separate STOP_SIGNALER
			clock: TIMER
			args: ARGUMENTS
			seconds: REAL_64
			through_parent: BOOLEAN
		do
			create env
			create clock.make
			create args
			create robot.make (env.namespace)
			create explorer.make_for_robot (robot)
			create master.make
			seconds := 20.0
			if args.argument_count >= 1 and then args.argument (1).is_double then
				seconds := args.argument (1).to_double
			end
			through_parent := args.argument_count >= 2 and then args.argument (2).same_string ("parent")
			explorer.set_parent (master)
			explorer.start
			clock.sleep (seconds)
			if through_parent then
				request_stop (master)
			else
				explorer.stop
			end
			print ("stop requested at " + clock.now.out + "%N")
			clock.sleep (1.0)
		end

	request_stop (s: separate STOP_SIGNALER)
			-- Stop `s' and its children.
		do
			s.request_stop
		end

end
