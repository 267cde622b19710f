note
	description: "Sets up a robot arm on its own processor."

class
	FACTORY

create
	make

feature {NONE} -- Initialization

	make
			-- Create and start two arms.
		local
			l_config: CONFIG
			l_arm: separate ARM
			l_other: separate ARM
		do
			create l_config.make (3)
			create l_arm.make (l_config) -- E: VUAR(3)
			create l_other.make_with_speed (l_config.speed)
			start (l_arm, l_config)
			start (l_other, l_config)
		end

feature -- Basic operations

	start (a_arm: separate ARM; a_config: CONFIG)
			-- Configure `a_arm' with `a_config' and move it.
		do
			a_arm.configure (a_config) -- E: VUAR(3)
			a_arm.move (a_config.speed)
		end

end
