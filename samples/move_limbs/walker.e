note
	description: "Walks: each step moves a leg and the opposite arm together, as one atomic action."

class
	WALKER

create
	make

feature {NONE} -- Initialization

	make (a_arm: separate ARM; a_leg: separate LEG; a_steps: INTEGER)
			-- Walker that will take `a_steps' steps with `a_arm' and `a_leg'.
		require
			some_steps: a_steps > 0
		do
			arm := a_arm
			leg := a_leg
			step_count := a_steps
			stride := Stride_angle
		end

feature -- Access

	step_count: INTEGER
			-- Steps to take.

	steps_taken: INTEGER
			-- Steps taken so far.

feature -- Basic operations

	walk
			-- Take every step.
		do
			from
			until
				steps_taken = step_count
			loop
				move_limbs (arm, leg)
				(create {EXECUTION_ENVIRONMENT}).sleep (Step_time)
			end
			print ("Walker: " + steps_taken.out + " steps taken%N")
		end

feature {NONE} -- Implementation

	move_limbs (a_arm: separate ARM; a_leg: separate LEG)
			-- Once both limbs are ready, step with `a_leg' and swing `a_arm' the other way.
		require
			arm_ready: a_arm.is_ready
			leg_ready: a_leg.is_ready
		do
			a_leg.step_to (stride)
			a_arm.swing_to (-stride)
			steps_taken := steps_taken + 1
			print ("Walker: step " + steps_taken.out + ", leg to " + a_leg.angle.out + ", arm to " + a_arm.angle.out + "%N")
			stride := -stride
		ensure
			one_more_step: steps_taken = old steps_taken + 1
			balanced: a_arm.angle = -a_leg.angle
		end

	arm: separate ARM
	leg: separate LEG
			-- The limbs moved.

	stride: INTEGER
			-- Hip angle of the next step.

	Stride_angle: INTEGER = 30
			-- Hip angle of a step, forward or back.

	Step_time: INTEGER_64 = 5_000_000
			-- Time between two steps, in nanoseconds.

invariant
	not_too_far: steps_taken <= step_count

end
