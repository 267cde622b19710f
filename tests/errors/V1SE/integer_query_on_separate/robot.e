note
	description: "A mobile robot with a pose and a battery level."

class
	ROBOT

create
	make

feature {NONE} -- Initialization

	make
			-- Robot at the origin, fully charged.
		do
			create pose.make (0.0, 0.0)
			battery_level := 100
		end

feature -- Access

	pose: POSE
			-- Where the robot is.

	battery_level: INTEGER
			-- Charge in percent.

end
