note
	description: "A two-finger gripper."

class
	GRIPPER

create
	make

feature {NONE} -- Initialization

	make
			-- Open gripper.
		do
			is_closed := False
		end

feature -- Status report

	is_closed: BOOLEAN
			-- Is the gripper closed?

feature -- Basic operations

	close
			-- Close the gripper.
		do
			is_closed := True
		end

end
