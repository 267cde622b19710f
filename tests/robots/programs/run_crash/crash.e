class
	CRASH

create
	make

feature

	make
			-- Drive forward, then fail after one second with the robot still commanded to move.
		local
			env: ROBOT_ENVIRONMENT
			drive: separate DIFFERENTIAL_DRIVE
		do
			create env
			create drive.make (env.namespace + "/cmd_vel", env.max_linear, env.max_angular)
			go (drive)
			(create {EXECUTION_ENVIRONMENT}).sleep (1_000_000_000)
			check
				never_here: False
			end
		end

	go (d: separate DIFFERENTIAL_DRIVE)
		do
			d.send (0.1, 0.0)
		end

end
