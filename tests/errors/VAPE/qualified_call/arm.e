class
	ARM

create
	make

feature {NONE} -- Initialization

	make (a_robot: ROBOT)
			-- An arm of `a_robot'.
		do
			robot := a_robot
		end

feature -- Basic operations

	move (distance: INTEGER)
			-- Move by `distance'; every client may call it, but only ARM may test its precondition.
		require
			calibrated: robot.is_calibrated -- E: VAPE@22
		do
		end

feature -- Access

	robot: ROBOT
			-- Owner.

end
