note
	description: "A mobile robot with a pose."

class
	ROBOT

create
	make

feature {NONE} -- Initialization

	make
			-- Robot at the origin.
		do
			create pose.make (0.0, 0.0)
		end

feature -- Access

	pose: POSE
			-- Where the robot is.

end
