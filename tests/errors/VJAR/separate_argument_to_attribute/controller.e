note
	description: "Drives a motor and writes to a log."

class
	CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_motor: separate MOTOR; a_log: separate LOG)
			-- Controller for `a_motor', logging to `a_log'.
		do
			motor := a_motor -- E: VJAR
			log := a_log
		end

feature -- Basic operations

	check_motor (a_motor: separate MOTOR)
			-- Check that `a_motor' is running.
		local
			l_motor: MOTOR
			l_any: separate ANY
		do
			l_motor := a_motor -- E: VJAR
			l_any := a_motor
			if a_motor.speed = 0 then
				a_motor.set_speed (10)
			end
		end

feature -- Access

	motor: MOTOR
			-- The motor driven.

	log: separate LOG
			-- Where events are written.

end
