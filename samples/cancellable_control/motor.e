note
	description: "Stand-in for a wheel motor: a speed that can be set within limits."

class
	MOTOR

create
	make

feature {NONE} -- Initialization

	make
			-- Motor at rest.
		do
			speed := 0
		ensure
			at_rest: speed = 0
		end

feature -- Access

	speed: INTEGER
			-- Current speed, in millimetres per second.

	command_count: INTEGER
			-- Number of speed commands received.

feature -- Element change

	set_speed (a_speed: INTEGER)
			-- Run at `a_speed'.
		require
			allowed: 0 <= a_speed and a_speed <= Max_speed
		do
			speed := a_speed
			command_count := command_count + 1
		ensure
			speed_set: speed = a_speed
			counted: command_count = old command_count + 1
		end

feature -- Constants

	Max_speed: INTEGER = 100
			-- Top speed.

invariant
	speed_allowed: 0 <= speed and speed <= Max_speed

end
