note
	description: "Settings for a robot arm."

class
	CONFIG

create
	make

feature {NONE} -- Initialization

	make (a_speed: INTEGER)
			-- Settings with `a_speed'.
		do
			speed := a_speed
		end

feature -- Access

	speed: INTEGER
			-- Joint speed.

end
