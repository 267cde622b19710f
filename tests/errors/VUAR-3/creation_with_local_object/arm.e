note
	description: "A robot arm."

class
	ARM

create
	make,
	make_with_speed

feature {NONE} -- Initialization

	make (a_config: CONFIG)
			-- Arm using `a_config'.
		do
			config := a_config
		end

	make_with_speed (a_speed: INTEGER)
			-- Arm with its own settings at `a_speed'.
		do
			create config.make (a_speed)
		end

feature -- Access

	config: CONFIG
			-- Settings in use.

	position: INTEGER
			-- Current joint position.

feature -- Basic operations

	configure (a_config: CONFIG)
			-- Use `a_config'.
		do
			config := a_config
		end

	move (a_speed: INTEGER)
			-- Move one step at `a_speed'.
		do
			position := position + a_speed
		end

end
