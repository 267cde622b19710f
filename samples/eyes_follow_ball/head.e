note
	description: "Stand-in for the robot's head: the eyes pan left and right, within limits."

class
	HEAD

create
	make

feature {NONE} -- Initialization

	make
			-- Head looking straight ahead.
		do
			pan := 0
		ensure
			ahead: pan = 0
		end

feature -- Access

	pan: INTEGER
			-- Direction the eyes look at, in degrees (positive to the left).

	move_count: INTEGER
			-- Number of turns so far.

	pan_towards (a_bearing: INTEGER): INTEGER
			-- The pan that looks as close to `a_bearing' as the head can turn.
		do
			Result := a_bearing.max (-Max_pan).min (Max_pan)
		ensure
			reachable: -Max_pan <= Result and Result <= Max_pan
		end

feature -- Status report

	is_facing (a_bearing: INTEGER): BOOLEAN
			-- Do the eyes look as close to `a_bearing' as they can?
		do
			Result := pan = pan_towards (a_bearing)
		end

feature -- Basic operations

	turn_to (a_pan: INTEGER)
			-- Turn the eyes to `a_pan'.
		require
			reachable: -Max_pan <= a_pan and a_pan <= Max_pan
		do
			pan := a_pan
			move_count := move_count + 1
		ensure
			turned: pan = a_pan
			counted: move_count = old move_count + 1
		end

feature -- Constants

	Max_pan: INTEGER = 45
			-- Widest angle the eyes can turn to, on either side.

invariant
	within_limits: -Max_pan <= pan and pan <= Max_pan

end
