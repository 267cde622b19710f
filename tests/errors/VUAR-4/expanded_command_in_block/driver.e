note
	description: "Drives a wheel motor with commands."

class
	DRIVER

create
	make

feature {NONE} -- Initialization

	make
			-- Create the motor and send it one command.
		local
			cmd: MOTOR_COMMAND
		do
			create motor.make
			cmd.set ("forward", 30)
			separate motor as m do
				m.execute (cmd) -- E: VUAR(4)
				m.set_speed (cmd.speed)
			end
		end

feature -- Access

	motor: separate WHEEL_MOTOR
			-- The motor driven.

end
