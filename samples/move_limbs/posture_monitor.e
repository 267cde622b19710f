note
	description: "[
		Looks at both limbs at once, now and then, and checks the posture is balanced (the arm
		opposite the leg): it never sees a step half done, because steps are atomic.
	]"

class
	POSTURE_MONITOR

create
	make

feature {NONE} -- Initialization

	make (a_arm: separate ARM; a_leg: separate LEG; a_checks: INTEGER)
			-- Monitor that will check `a_arm' and `a_leg' `a_checks' times.
		do
			arm := a_arm
			leg := a_leg
			check_count := a_checks
		end

feature -- Access

	check_count: INTEGER
			-- Checks to make.

	checks_made: INTEGER
			-- Checks made so far.

feature -- Basic operations

	watch
			-- Make every check.
		do
			from
			until
				checks_made = check_count
			loop
				check_posture (arm, leg)
				(create {EXECUTION_ENVIRONMENT}).sleep (Check_period)
			end
			print ("Monitor: posture balanced in all " + checks_made.out + " checks%N")
		end

feature {NONE} -- Implementation

	check_posture (a_arm: separate ARM; a_leg: separate LEG)
			-- Once both limbs are ready, look at them together.
		require
			arm_ready: a_arm.is_ready
			leg_ready: a_leg.is_ready
		do
			checks_made := checks_made + 1
		ensure
			balanced: a_arm.angle = -a_leg.angle
			as_many_moves: a_arm.move_count = a_leg.move_count
		end

	arm: separate ARM
	leg: separate LEG
			-- The limbs watched.

	Check_period: INTEGER_64 = 3_000_000
			-- Time between two checks, in nanoseconds.

end
