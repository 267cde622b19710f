note
	description: "[
		A robot walks: a walker moves a leg and the opposite arm in one atomic action, waiting
		until both are calibrated; a monitor checks the posture between steps.
	]"

class
	MOVE_LIMBS

create
	make

feature {NONE} -- Initialization

	make
			-- Create the limbs and the processors using them, and start them.
		local
			l_arm: separate ARM
			l_leg: separate LEG
			l_walker: separate WALKER
			l_monitor: separate POSTURE_MONITOR
			l_calibrator: separate CALIBRATOR
		do
			create l_arm.make
			create l_leg.make
			create l_walker.make (l_arm, l_leg, Step_count)
			create l_monitor.make (l_arm, l_leg, Check_count)
			create l_calibrator.make (l_arm, l_leg)
			start_walker (l_walker)
			start_monitor (l_monitor)
			start_calibrator (l_calibrator)
		end

feature {NONE} -- Implementation

	start_walker (a_walker: separate WALKER)
			-- Let `a_walker' walk.
		do
			a_walker.walk
		end

	start_monitor (a_monitor: separate POSTURE_MONITOR)
			-- Let `a_monitor' watch the limbs.
		do
			a_monitor.watch
		end

	start_calibrator (a_calibrator: separate CALIBRATOR)
			-- Let `a_calibrator' make the limbs ready.
		do
			a_calibrator.calibrate_all
		end

	Step_count: INTEGER = 6
			-- Steps to walk.

	Check_count: INTEGER = 8
			-- Posture checks to make.

end
