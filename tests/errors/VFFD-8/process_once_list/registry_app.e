note
	description: "Keeps every robot of the program in one registry."

class
	REGISTRY_APP

create
	make

feature {NONE} -- Initialization

	make
			-- Create a robot and register it.
		local
			l_robot: separate ROBOT
		do
			create l_robot.make (1)
			registry.extend (l_robot)
			enroll (shared_registry, l_robot)
		end

feature -- Access

	registry: ARRAYED_LIST [separate ROBOT] -- E: VFFD(8)
			-- Every robot of the program.
		once ("PROCESS")
			create Result.make (4)
		end

	shared_registry: separate ARRAYED_LIST [separate ROBOT]
			-- Every robot of the program, on a processor of its own.
		once ("PROCESS")
			create Result.make (4)
		end

feature -- Basic operations

	enroll (a_registry: separate ARRAYED_LIST [separate ROBOT]; a_robot: separate ROBOT)
			-- Add `a_robot' to `a_registry'.
		do
			a_registry.extend (a_robot)
		end

end
