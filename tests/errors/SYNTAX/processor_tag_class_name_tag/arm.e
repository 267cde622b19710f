note
	description: "A robot arm on an assembly line."

class
	ARM

create
	make

feature {NONE} -- Initialization

	make
			-- Arm in its rest position.
		do
			position := 0
		end

feature -- Access

	position: INTEGER
			-- Joint position.

feature -- Basic operations

	move
			-- Move one step.
		do
			position := position + 1
		end

end
