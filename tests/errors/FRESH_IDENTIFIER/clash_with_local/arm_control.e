note
	description: "Moves an arm motor."

class
	ARM_CONTROL

create
	make

feature {NONE} -- Initialization

	make
			-- Create the motor and set its speed.
		local
			m: INTEGER
		do
			create motor.make (1)
			m := 5
			separate motor as m do -- E: FRESH_IDENTIFIER
				print ("motor reserved%N")
			end
			separate motor as l_motor do
				l_motor.set_speed (m)
			end
		end

feature -- Access

	motor: separate MOTOR
			-- The arm's motor.

end
