note
	description: "Asks a path planner for its goal."

class
	PLANNER_CLIENT

create
	make

feature {NONE} -- Initialization

	make
			-- Create a planner and print its goal.
		local
			l_planner: separate PLANNER
			l_goal: POSE
		do
			create l_planner.make
			l_goal := goal_of (l_planner)
			print (l_goal.x)
			l_goal := goal_copy (l_planner)
			print (l_goal.y)
		end

feature -- Access

	goal_of (a_planner: separate PLANNER): POSE
			-- The goal of `a_planner'.
		do
			Result := a_planner.goal -- E: VJAR
		end

	goal_copy (a_planner: separate PLANNER): POSE
			-- A copy of the goal of `a_planner'.
		do
			create Result.make (a_planner.goal.x, a_planner.goal.y)
		end

end
