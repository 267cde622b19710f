note
	description: "Starts a patrol robot unless it is already running."

class
	PATROL

create
	make

feature {NONE} -- Initialization

	make
			-- Create the robot and start it.
		do
			create robot.make
			separate is_running as r do -- E: V1SE
				print (r)
			end
			separate robot as b do
				b.start
				is_running := b.is_moving
			end
		end

feature -- Access

	robot: separate PATROL_ROBOT
			-- The robot on patrol.

	is_running: BOOLEAN
			-- Has the patrol started?

end
