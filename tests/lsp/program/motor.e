note
	description: "A wheel motor with a settable speed."

class
	MOTOR

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER)
			-- Motor number `an_id', stopped.
		do
			id := an_id
		end

feature -- Access

	id: INTEGER
			-- Motor number.

	speed: INTEGER
			-- Current speed in percent.

feature -- Element change

	set_speed (a_speed: INTEGER)
			-- Run at `a_speed'.
		require
			in_range: a_speed >= -100 and a_speed <= 100
		do
			speed := a_speed
		ensure
			speed_set: speed = a_speed
		end

feature {MOTOR} -- Implementation

	calibrate
			-- Reset the speed sensor (for other motors only).
		do
			speed := 0
		end

end
