note
	description: "Remembers the name of the robot seen last."

class
	NAME_CACHE

create
	make

feature {NONE} -- Initialization

	make
			-- Create a robot and remember its name.
		local
			l_robot: separate ROBOT
		do
			last_name := "none"
			create l_robot.make ("Rover")
			read_name (l_robot)
		end

feature -- Basic operations

	read_name (a_robot: separate ROBOT)
			-- Remember the name of `a_robot'.
		do
			last_name := a_robot.name -- E: VJAR
			create last_name.make_from_separate (a_robot.name)
			shared_name := a_robot.name
			print (last_name + "%N")
		end

feature -- Access

	last_name: STRING
			-- Copy of the name read last.

	shared_name: detachable separate STRING
			-- The name itself, on the robot's processor.

end
