note
	description: "Starts a wheel motor on its own processor and drives it."

class
	ROBOT_APP

create
	make

feature {NONE} -- Initialization

	make
			-- Create the motor and set its speed.
		do
			create motor.make (1)
			motor.set_speed (40) -- E: VUTA(3)
			drive (motor, 60)
			if motor.speed > 50 then -- E: VUTA(3)
				print ("fast%N")
			end
			separate motor as m do
				m.set_speed (20)
				print ("motor " + m.id.out + " slowed down%N")
			end
		end

feature {NONE} -- Implementation

	drive (a_motor: separate MOTOR; a_speed: INTEGER)
			-- Set `a_motor' to `a_speed' and report it.
		do
			a_motor.set_speed (a_speed)
			print ("motor " + a_motor.id.out + " at " + a_motor.speed.out + "%N")
		end

	motor: separate MOTOR
			-- The wheel motor, on its own processor.

end
