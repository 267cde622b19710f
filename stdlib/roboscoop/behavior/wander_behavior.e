note
	description: "[
		Wandering: the exploration's three controllers plus a fourth that, every few seconds
		(at random, between `min_gap' and `max_gap'), starts a slow random turn when no
		maneuver is under way; so the robot meanders instead of driving straight from wall to
		wall.
	]"

class
	WANDER_BEHAVIOR

inherit
	EXPLORATION_BEHAVIOR
		redefine
			launch_more
		end

create
	make, make_for_robot

feature -- Access

	min_gap: REAL_64 = 2.0
			-- Shortest time between two random turns (s).

	max_gap: REAL_64 = 6.0
			-- Longest time between two random turns (s).

feature {NONE} -- Implementation

	launch_more (a_stop: separate STOP_SIGNALER; a_maneuver: separate MANEUVER_SIGNALER)
			-- <Precursor>
		local
			meander: separate SIMPLE_CONTROLLER
		do
			create meander.make_with_maneuver (a_stop, range_signaler, a_maneuver, drive, linear_speed, angular_speed, period)
			start_meander (meander)
		end

	start_meander (a_meander: separate SIMPLE_CONTROLLER)
			-- Set the meandering controller going.
		do
			a_meander.set_seed (seed + 7)
			a_meander.run_swerve (min_gap, max_gap)
		end

end
