note
	description: "Stand-in for a robot arm: swings forward and back from the shoulder once calibrated."

class
	ARM

create
	make

feature {NONE} -- Initialization

	make
			-- Arm hanging down, not calibrated yet.
		do
			angle := 0
		ensure
			hanging: angle = 0
			not_ready: not is_ready
		end

feature -- Access

	angle: INTEGER
			-- Shoulder angle, in degrees (positive forward).

	move_count: INTEGER
			-- Number of swings so far.

feature -- Status report

	is_ready: BOOLEAN
			-- Has the arm been calibrated, so that it may move?

feature -- Basic operations

	calibrate
			-- Find the arm's zero position.
		do
			is_ready := True
		ensure
			ready: is_ready
		end

	swing_to (a_angle: INTEGER)
			-- Swing the arm to `a_angle'.
		require
			ready: is_ready
			in_reach: -Max_angle <= a_angle and a_angle <= Max_angle
		do
			angle := a_angle
			move_count := move_count + 1
		ensure
			swung: angle = a_angle
		end

feature -- Constants

	Max_angle: INTEGER = 60
			-- Widest swing, forward or back.

invariant
	in_reach: -Max_angle <= angle and angle <= Max_angle
	still_until_ready: not is_ready implies move_count = 0

end
