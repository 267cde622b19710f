note
	description: "A robot that patrols a corridor."

class
	PATROL_ROBOT

create
	make

feature {NONE} -- Initialization

	make
			-- Robot at rest.
		do
			is_moving := False
		end

feature -- Status report

	is_moving: BOOLEAN
			-- Is the robot moving?

feature -- Basic operations

	start
			-- Start moving.
		do
			is_moving := True
		end

end
