note
	description: "[
		Chameneos: creatures of three colours meet in pairs at a meeting place; after a
		meeting each takes the colour complementary to the two it saw. The place closes
		after a fixed number of meetings.
	]"

class
	CHAMENEOS

create
	make

feature {NONE} -- Initialization

	make
			-- Start the creatures and wait until the place closes.
		local
			l_place: separate MEETING_PLACE
			l_creature: separate CREATURE
			l_colours: ARRAY [INTEGER]
			i: INTEGER
		do
			l_colours := <<Blue, Red, Yellow, Blue>>
			create l_place.make (Meeting_count, l_colours.count)
			from
				i := l_colours.lower
			until
				i > l_colours.upper
			loop
				create l_creature.make (i, l_colours.item (i), l_place)
				start (l_creature)
				i := i + 1
			end
			wait_for_closing (l_place)
		end

feature {NONE} -- Implementation

	start (a_creature: separate CREATURE)
			-- Let `a_creature' go to meetings until the place closes.
		do
			a_creature.live
		end

	wait_for_closing (a_place: separate MEETING_PLACE)
			-- Report once `a_place' has closed.
		require
			closed: a_place.is_closed
		do
			print ("All " + Meeting_count.out + " meetings took place%N")
		end

	Meeting_count: INTEGER = 12
			-- Meetings before the place closes.

	Blue: INTEGER = 1
	Red: INTEGER = 2
	Yellow: INTEGER = 3
			-- Colours.

end
