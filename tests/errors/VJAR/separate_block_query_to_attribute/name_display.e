note
	description: "Shows the name of a robot."

class
	NAME_DISPLAY

create
	make

feature {NONE} -- Initialization

	make
			-- Create a robot and copy its name.
		do
			name := "unknown"
			create robot.make ("Scout")
			separate robot as r do
				name := r.name -- E: VJAR
				create name.make_from_separate (r.name)
				if r.name.count > 3 then
					print (name + "%N")
				end
			end
		end

feature -- Access

	robot: separate ROBOT
			-- The robot shown.

	name: STRING
			-- Copy of its name.

end
