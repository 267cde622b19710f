note
	description: "[
		A behaviour that patrols a room with a PATROL_CONTROLLER (exercise 3, README.md): `start'
		(inherited) makes the behaviour's STOP_SIGNALER and calls `launch'; `stop', or a stop of
		the parent signaler (`set_parent'), stops the controller through the signaler tree.
		Complete `launch'.
	]"

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
		do
			-- TODO
		end

end
