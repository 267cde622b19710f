note
	description: "Drives a wheel motor on its own processor."

class
	ROBOT_APP

create
	make

feature {NONE} -- Initialization

	make
			-- Create the motor and drive it.
		local
			count: INTEGER
		do
			create motor.make (1)
			motor.set_speed (40)
			drive (motor, 60)
			count := count + 1
			print (count.out + "%N")
		end

feature -- Access

	motor: separate MOTOR
			-- The left wheel's motor.

feature -- Basic operations

	drive (a_motor: separate MOTOR; a_speed: INTEGER)
			-- Run `a_motor' at `a_speed'.
		do
			a_motor.set_sped (a_speed)
		end

end
