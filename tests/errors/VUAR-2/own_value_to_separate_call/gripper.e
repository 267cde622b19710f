note
	description: "A gripper on a robot arm."

class
	GRIPPER

create
	make

feature {NONE} -- Initialization

	make
			-- Gripper holding a hook.
		do
			create tool.make ("hook")
		end

feature -- Access

	tool: TOOL
			-- Tool held.

	grips: INTEGER
			-- Number of grips made.

feature -- Basic operations

	grip (a_tool: TOOL)
			-- Grip with `a_tool'.
		do
			grips := grips + 1
		end

	grip_any (a_tool: separate TOOL)
			-- Grip with `a_tool', wherever it lives.
		do
			grips := grips + 1
		end

end
