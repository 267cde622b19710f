note
	description: "A motor with a settable speed."

class
	MOTOR

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

feature -- Element change

	set_speed (a_speed: INTEGER)
			-- Run at `a_speed'.
		do
			speed := a_speed
		end

end
