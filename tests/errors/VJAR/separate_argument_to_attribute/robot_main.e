note
	description: "Wires a controller to a motor and a log."

class
	ROBOT_MAIN

create
	make

feature {NONE} -- Initialization

	make
			-- Create a motor, a log and their controller.
		local
			l_motor: separate MOTOR
			l_log: separate LOG
			l_controller: CONTROLLER
		do
			create l_motor.make
			create l_log.make
			create l_controller.make (l_motor, l_log)
			l_controller.check_motor (l_motor)
		end

end
