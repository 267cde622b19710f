note
	description: "[
		The paper's exploration (section IV) as a program: the frame around EXPLORATION_BEHAVIOR's
		`start', whose `launch' sets three SIMPLE_CONTROLLERs going: `go_straight',
		`turn_to_avoid_obstacles' and `stop_on_emergency', repeating the paper's `go', `turn' and
		`stop' on the robot.
	]"

class
	EXPLORATION

create
	make

feature {NONE} -- Initialization

	make
			-- Explore with the robot of the run.
		local
			env: ROBOT_ENVIRONMENT
			robot: separate THYMIO_ROBOT
			explorer: EXPLORATION_BEHAVIOR
		do
			create env
			create robot.make (env.namespace)
			create explorer.make_simple (robot)
			explorer.start
		end

end
