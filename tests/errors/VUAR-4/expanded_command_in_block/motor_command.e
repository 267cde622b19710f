note
	description: "A named speed command, copied on assignment."

expanded class
	MOTOR_COMMAND

inherit
	ANY
		redefine
			default_create
		end

feature {NONE} -- Initialization

	default_create
			-- A stop command.
		do
			name := "stop"
		end

feature -- Access

	name: STRING
			-- Name of the command.

	speed: INTEGER
			-- Speed asked for.

feature -- Element change

	set (a_name: STRING; a_speed: INTEGER)
			-- Command `a_name' at `a_speed'.
		do
			name := a_name
			speed := a_speed
		end

end
