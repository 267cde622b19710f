note
	description: "A mobile robot with a pose and a battery of its own."

class
	ROBOT

create
	make

feature {NONE} -- Initialization

	make
			-- Robot at the origin with a full battery.
		do
			create pose.make (0.0, 0.0)
			create battery.make
		end

feature -- Access

	pose: POSE
			-- Where the robot is.

	battery: separate BATTERY
			-- The battery, handled by its own processor.

end
