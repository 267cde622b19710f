note
	description: "A wheel motor."

class
	WHEEL_MOTOR

create
	make

feature {NONE} -- Initialization

	make
			-- Stopped motor.
		do
			speed := 0
		end

feature -- Access

	speed: INTEGER
			-- Current speed.

feature -- Basic operations

	execute (a_command: MOTOR_COMMAND)
			-- Follow `a_command'.
		do
			speed := a_command.speed
		end

	set_speed (a_speed: INTEGER)
			-- Run at `a_speed'.
		do
			speed := a_speed
		end

end
