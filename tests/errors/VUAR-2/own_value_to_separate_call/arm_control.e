note
	description: "Controls a gripper on its own processor."

class
	ARM_CONTROL

create
	make

feature {NONE} -- Initialization

	make
			-- Make a gripper and use it.
		local
			l_gripper: separate GRIPPER
		do
			create l_gripper.make
			use (l_gripper)
		end

feature -- Basic operations

	use (a_gripper: separate GRIPPER)
			-- Grip with the gripper's own tool.
		do
			a_gripper.grip (a_gripper.tool) -- E: VUAR(2)
			a_gripper.grip_any (a_gripper.tool)
			print (a_gripper.grips.out + "%N")
		end

end
