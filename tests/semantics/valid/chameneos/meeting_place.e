note
	description: "Where creatures meet in pairs; each learns the colour of its partner."

class
	MEETING_PLACE

create
	make

feature {NONE} -- Initialization

	make (a_meetings, a_creature_count: INTEGER)
			-- Place open for `a_meetings' meetings among `a_creature_count' creatures.
		require
			some_meetings: a_meetings > 0
			some_creatures: a_creature_count >= 2
		do
			meetings_left := a_meetings
			create partner_colours.make_filled (0, 1, a_creature_count)
		ensure
			meetings_set: meetings_left = a_meetings
		end

feature -- Access

	meetings_left: INTEGER
			-- Meetings still to take place.

	partner_colour (an_id: INTEGER): INTEGER
			-- Colour of the partner creature `an_id' met last, 0 if it has not met one yet.
		require
			valid_id: is_valid_id (an_id)
		do
			Result := partner_colours.item (an_id)
		end

feature -- Status report

	is_valid_id (an_id: INTEGER): BOOLEAN
			-- Is `an_id' the number of a creature? (Exported: the preconditions use it, VAPE.)
		do
			Result := partner_colours.valid_index (an_id)
		end

	is_closed: BOOLEAN
			-- Have all meetings taken place?
		do
			Result := meetings_left = 0
		end

	has_partner (an_id: INTEGER): BOOLEAN
			-- Has creature `an_id' met a partner it has not left yet?
		require
			valid_id: is_valid_id (an_id)
		do
			Result := partner_colour (an_id) /= 0
		end

feature -- Element change

	enter (an_id, a_colour: INTEGER)
			-- Let creature `an_id', of `a_colour', wait for a partner or meet the one waiting.
		require
			open: not is_closed
			valid_id: is_valid_id (an_id)
			not_paired: not has_partner (an_id)
		do
			if waiting_id = 0 then
				waiting_id := an_id
				waiting_colour := a_colour
			else
				partner_colours.put (a_colour, waiting_id)
				partner_colours.put (waiting_colour, an_id)
				waiting_id := 0
				meetings_left := meetings_left - 1
			end
		end

	leave (an_id: INTEGER)
			-- Let creature `an_id' leave after its meeting.
		require
			valid_id: is_valid_id (an_id)
		do
			partner_colours.put (0, an_id)
		ensure
			left: not has_partner (an_id)
		end

feature {NONE} -- Implementation

	waiting_id: INTEGER
			-- Creature waiting for a partner, 0 if none.

	waiting_colour: INTEGER
			-- Its colour.

	partner_colours: ARRAY [INTEGER]
			-- Colour of each creature's last partner, 0 once it has left.

invariant
	non_negative: meetings_left >= 0

end
