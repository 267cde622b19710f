note
	description: "Exercise 3's reference solution (exercises/3_behavior): a patrol with a stop signaler tree."

class
	PATROL_BEHAVIOR

inherit
	BEHAVIOR

create
	make

feature {NONE} -- Initialization

	make (a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Patrol with `a_range' and `a_drive'.
		do
			range := a_range
			drive := a_drive
		end

feature -- Access

	range: separate RANGE_SIGNALER
			-- What is around the robot.

	drive: separate DIFFERENTIAL_DRIVE
			-- Its wheels.

feature {NONE} -- Implementation

	launch (a_stop: separate STOP_SIGNALER)
			-- Give the controller a stop signaler of its own, a child of `a_stop', then create the
			-- controller with it and set it running (asynchronously).
		local
			own: separate STOP_SIGNALER
			controller: separate PATROL_CONTROLLER
		do
			create own.make
			adopt (a_stop, own)
			create controller.make (own, range, drive)
			run (controller)
		end

	run (a_controller: separate PATROL_CONTROLLER)
			-- Set `a_controller' going.
		do
			a_controller.run
		end

end
