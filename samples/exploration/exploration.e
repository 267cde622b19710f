note
	description: "[
		Exploration (the Roboscoop paper, section IV): a Thymio explores its world with three
		separate controllers launched together (go straight, avoid obstacles and holes, stop on
		emergency) until the run ends.
	]"

class
	EXPLORATION

create
	make

feature {NONE} -- Initialization

	make
			-- Start exploring with the robot of this run.
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			explorer: EXPLORATION_BEHAVIOR
		do
			create env
			create robot.make (env.namespace)
			create explorer.make_for_robot (robot)
			explorer.start
			print ("Exploring with " + robot.namespace + "%N")
		end

end
