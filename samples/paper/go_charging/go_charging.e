note
	description: "[
		The paper's `go_charging' as a program: when the battery falls below 20%, the robot goes to
		its charging station. `go_charging' is the paper's routine (a wait condition on the
		battery signaler); the frame makes the robot of the run and hands it its battery.
	]"

class
	GO_CHARGING

create
	make

feature {NONE} -- Initialization

	make
			-- Go charging when the battery is low.
		local
			env: ROBOT_ENVIRONMENT
			robot: separate THYMIO_ROBOT
		do
			create env
			create robot.make (env.namespace)
			go_charging (robot, battery_of (robot))
		end

feature -- The paper's listing

	go_charging (robot: separate ROBOT; battery: separate BATTERY_SIGNALER)
		require
			battery.charging_level < 0.2
		do
			robot.go_to_charging_station
		end

feature {NONE} -- Frame

	battery_of (a_robot: separate THYMIO_ROBOT): separate BATTERY_SIGNALER
			-- The battery signaler of `a_robot'.
		do
			Result := a_robot.battery
		end

end
