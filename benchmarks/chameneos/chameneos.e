note
	description: "[
		SCOOP/Qs chameneos benchmark (chameneos-redux): Creature_count creatures, each its own
		processor, meet in pairs at a mall and take complementary colours, N meetings in all.
		N is the first argument (default 300000), Creature_count the second (default 10).
		Prints the number of meetings the creatures saw, which must be 2 * N.
	]"

class
	CHAMENEOS

inherit
	COLOURS

	ARGUMENTS

create
	make

feature {NONE} -- Initialization

	make
			-- Create the mall and the creatures, launch them, then add up their meetings.
		local
			l_mall: separate MALL
			l_creature: separate CREATURE
			l_team: ARRAYED_LIST [separate CREATURE]
			l_meetings, l_seen: INTEGER
		do
			l_meetings := Default_meetings
			if argument_count >= 1 then
				l_meetings := argument (1).to_integer
			end
			creature_count := Default_creatures
			if argument_count >= 2 then
				creature_count := argument (2).to_integer
			end
			create l_mall.make (l_meetings, creature_count)
			create l_team.make (creature_count)
			across 1 |..| creature_count as i loop
				create l_creature.make (i.item, start_colour (i.item), l_mall)
				l_team.extend (l_creature)
			end
			across l_team as c loop
				launch (c.item)
			end
			across l_team as c loop
				l_seen := l_seen + meetings_of (c.item)
			end
			print ("chameneos: creatures=" + creature_count.out + " meetings=" + l_meetings.out + " seen=" + l_seen.out + "%N")
		end

feature {NONE} -- Implementation

	launch (c: separate CREATURE)
			-- Let `c' go to meetings until the mall is closed.
		do
			c.live
		end

	meetings_of (c: separate CREATURE): INTEGER
			-- Meetings `c' had, once it is done (the query waits for it).
		do
			Result := c.count
		end

	start_colour (i: INTEGER): INTEGER
			-- Colour of creature `i' at the start.
		require
			positive: i >= 1
		do
			Result := Start_colours [(i - 1) \\ Start_colours.count + 1]
		ensure
			valid_colour: is_colour (Result)
		end

	Start_colours: ARRAY [INTEGER]
			-- The colours given in turn to the creatures.
		once
			Result := <<Blue, Red, Yellow, Red, Yellow, Blue, Red, Yellow, Red, Blue>>
		end

	creature_count: INTEGER
			-- Number of creatures.

	Default_creatures: INTEGER = 10
			-- Number of creatures when no second argument is given.

	Default_meetings: INTEGER = 300_000
			-- Meetings when no argument is given.

end
