note
	description: "A path planner with a goal."

class
	PLANNER

create
	make

feature {NONE} -- Initialization

	make
			-- Planner heading for (3, 4).
		do
			create goal.make (3.0, 4.0)
		end

feature -- Access

	goal: POSE
			-- Where the robot should go.

end
