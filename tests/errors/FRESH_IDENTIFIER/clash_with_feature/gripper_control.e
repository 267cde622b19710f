note
	description: "Closes a gripper."

class
	GRIPPER_CONTROL

create
	make

feature {NONE} -- Initialization

	make
			-- Create the gripper and close it.
		do
			create gripper.make
			separate gripper as gripper do -- E: FRESH_IDENTIFIER
				print ("gripper reserved%N")
			end
			separate gripper as g do
				g.close
			end
		end

feature -- Access

	gripper: separate GRIPPER
			-- The gripper at the end of the arm.

end
