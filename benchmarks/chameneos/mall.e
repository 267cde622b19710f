note
	description: "[
		Where chameneos meet: the first creature to arrive waits, the next one meets it; after
		a given number of meetings the mall is closed.
	]"

class
	MALL

inherit
	COLOURS

create
	make

feature {NONE} -- Initialization

	make (a_meetings, a_creatures: INTEGER)
			-- Mall open for `a_meetings' meetings of creatures numbered 1 to `a_creatures'.
		require
			non_negative_meetings: a_meetings >= 0
			some_creatures: a_creatures >= 2
		do
			left := a_meetings
			create outcomes.make_filled (0, 1, a_creatures)
			create partners.make_filled (0, 1, a_creatures)
		end

feature -- Access

	left: INTEGER
			-- Meetings still to take place.

	outcome_of (an_id: INTEGER): INTEGER
			-- What the last visit of creature `an_id' gave: `First', `Closed' or its partner's colour.
		do
			Result := outcomes [an_id]
		end

	partner_of (an_id: INTEGER): INTEGER
			-- Colour of the creature that met creature `an_id' while it waited.
		require
			has_partner: has_partner (an_id)
		do
			Result := partners [an_id]
		end

feature -- Status report

	has_partner (an_id: INTEGER): BOOLEAN
			-- Has creature `an_id', waiting, been met?
		do
			Result := partners [an_id] /= 0
		end

feature -- Element change

	arrive (an_id, a_colour: INTEGER)
			-- Creature `an_id' of `a_colour' comes: it waits, meets the waiting creature, or finds the mall closed.
		require
			valid_colour: is_colour (a_colour)
		do
			if left = 0 then
				outcomes [an_id] := Closed
			elseif waiting_id = 0 then
				waiting_id := an_id
				waiting_colour := a_colour
				outcomes [an_id] := First
			else
				partners [waiting_id] := a_colour
				outcomes [an_id] := waiting_colour
				waiting_id := 0
				left := left - 1
			end
		end

	forget_partner (an_id: INTEGER)
			-- Creature `an_id' has taken note of its partner.
		require
			has_partner: has_partner (an_id)
		do
			partners [an_id] := 0
		ensure
			forgotten: not has_partner (an_id)
		end

feature {NONE} -- Implementation

	waiting_id: INTEGER
			-- Creature waiting for a partner, 0 if none.

	waiting_colour: INTEGER
			-- Its colour.

	outcomes: ARRAY [INTEGER]
			-- Outcome of each creature's last visit.

	partners: ARRAY [INTEGER]
			-- Colour of the partner of each waiting creature once met, 0 otherwise.

invariant
	non_negative_left: left >= 0

end
