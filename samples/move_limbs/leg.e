note
	description: "Stand-in for a robot leg: steps forward and back from the hip once calibrated."

class
	LEG

create
	make

feature {NONE} -- Initialization

	make
			-- Leg straight down, not calibrated yet.
		do
			angle := 0
		ensure
			straight: angle = 0
			not_ready: not is_ready
		end

feature -- Access

	angle: INTEGER
			-- Hip angle, in degrees (positive forward).

	move_count: INTEGER
			-- Number of steps so far.

feature -- Status report

	is_ready: BOOLEAN
			-- Has the leg been calibrated, so that it may move?

feature -- Basic operations

	calibrate
			-- Find the leg's zero position.
		do
			is_ready := True
		ensure
			ready: is_ready
		end

	step_to (a_angle: INTEGER)
			-- Move the leg to `a_angle'.
		require
			ready: is_ready
			in_reach: -Max_angle <= a_angle and a_angle <= Max_angle
		do
			angle := a_angle
			move_count := move_count + 1
		ensure
			moved: angle = a_angle
		end

feature -- Constants

	Max_angle: INTEGER = 40
			-- Widest step, forward or back.

invariant
	in_reach: -Max_angle <= angle and angle <= Max_angle
	still_until_ready: not is_ready implies move_count = 0

end
