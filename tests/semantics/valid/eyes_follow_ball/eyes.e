note
	description: "Stand-in for the robot's eyes: a pan angle that can be set."

class
	EYES

create
	make

feature {NONE} -- Initialization

	make
			-- Eyes looking straight ahead.
		do
			pan := 0.0
		end

feature -- Access

	pan: REAL_64
			-- Angle of the eyes, in radians (positive to the left).

	move_count: INTEGER
			-- Number of moves so far.

feature -- Basic operations

	look_at (a_pan: REAL_64)
			-- Turn the eyes to `a_pan'.
		require
			in_range: -Max_pan <= a_pan and a_pan <= Max_pan
		do
			pan := a_pan
			move_count := move_count + 1
		ensure
			turned: pan = a_pan
		end

feature -- Constants

	Max_pan: REAL_64 = 1.2
			-- Widest angle the eyes can turn to.

end
