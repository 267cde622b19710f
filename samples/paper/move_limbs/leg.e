note
	description: "A robot's leg (a stand-in part): each move swings it to the other side."

class
	LEG

create
	make

feature {NONE} -- Initialization

	make
			-- At rest, straight down.
		do
		end

feature -- Access

	angle: INTEGER
			-- Swing (degrees, forward positive).

	move_count: INTEGER
			-- Moves so far.

feature -- Basic operations

	move
			-- Swing to the other side (forward first).
		do
			if angle > 0 then
				angle := -30
			else
				angle := 30
			end
			move_count := move_count + 1
			print ("Leg to " + angle.out + " degrees%N")
		ensure
			moved: move_count = old move_count + 1
		end

end
