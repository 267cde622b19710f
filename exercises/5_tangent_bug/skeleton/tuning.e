note
	description: "[
		The parameters TANGENT_BUG_BEHAVIOR runs with in exercise 5's world (README.md): the
		radius the planner keeps the robot's centre away from obstacles with, and the speed
		limits it drives at. Tune them.
	]"

class
	TUNING

feature -- Access

	Robot_radius: REAL_64 = 0.25
			-- The radius the planner assumes (m); the robot's own is 0.15.

	Linear_speed: REAL_64 = 0.5
			-- The fastest it drives (m/s, at most 0.5).

	Angular_speed: REAL_64 = 2.0
			-- The fastest it turns (rad/s, at most 2.0).

end
