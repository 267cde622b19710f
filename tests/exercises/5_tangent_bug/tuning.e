note
	description: "[
		Exercise 5's reference solution (exercises/5_tangent_bug): the true radius lets the
		planner see the gap; slower speeds keep the robot from overshooting the gap's edges.
	]"

class
	TUNING

feature -- Access

	Robot_radius: REAL_64 = 0.15
			-- The radius the planner assumes (m); the robot's own is 0.15.

	Linear_speed: REAL_64 = 0.3
			-- The fastest it drives (m/s, at most 0.5).

	Angular_speed: REAL_64 = 1.5
			-- The fastest it turns (rad/s, at most 2.0).

end
