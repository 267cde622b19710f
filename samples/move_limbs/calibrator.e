note
	description: "Calibrates the limbs one after the other, which takes a while for each."

class
	CALIBRATOR

create
	make

feature {NONE} -- Initialization

	make (a_arm: separate ARM; a_leg: separate LEG)
			-- Calibrator for `a_arm' and `a_leg'.
		do
			arm := a_arm
			leg := a_leg
		end

feature -- Basic operations

	calibrate_all
			-- Calibrate the leg, then the arm.
		do
			(create {EXECUTION_ENVIRONMENT}).sleep (Calibration_time)
			calibrate_leg (leg)
			(create {EXECUTION_ENVIRONMENT}).sleep (Calibration_time)
			calibrate_arm (arm)
		end

feature {NONE} -- Implementation

	calibrate_leg (a_leg: separate LEG)
			-- Calibrate `a_leg'.
		do
			a_leg.calibrate
			print ("Calibrator: leg ready%N")
		end

	calibrate_arm (a_arm: separate ARM)
			-- Calibrate `a_arm'.
		do
			a_arm.calibrate
			print ("Calibrator: arm ready%N")
		end

	arm: separate ARM
	leg: separate LEG
			-- The limbs to calibrate.

	Calibration_time: INTEGER_64 = 20_000_000
			-- Time to calibrate one limb, in nanoseconds.

end
