note
	description: "Picks parts from a conveyor belt."

class
	PICKER

create
	make

feature {NONE} -- Initialization

	make
			-- Create the conveyor and pick two parts.
		do
			create conveyor.make (5)
			pick
			pick_from (conveyor)
		end

feature -- Basic operations

	pick
			-- Take the next part, once one has arrived.
		require
			has_part: conveyor.count > 0 -- E: VUTA(3)
		do
			print ("picking%N")
		end

	pick_from (a_conveyor: separate CONVEYOR)
			-- Take the next part from `a_conveyor', once one has arrived.
		require
			has_part: a_conveyor.count > 0
		do
			a_conveyor.remove_part
		ensure
			one_less: a_conveyor.count = old a_conveyor.count - 1
		end

feature -- Access

	conveyor: separate CONVEYOR
			-- The belt bringing parts.

invariant
	conveyor_exists: conveyor /= Void
	never_negative: conveyor.count >= 0 -- E: VUTA(3)

end
