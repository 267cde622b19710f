note
	description: "A chameneos: goes to the mall again and again; after each meeting takes the complementary colour."

class
	CREATURE

inherit
	COLOURS

create
	make

feature {NONE} -- Initialization

	make (an_id, a_colour: INTEGER; a_mall: separate MALL)
			-- Creature `an_id' of `a_colour' visiting `a_mall'.
		require
			valid_colour: is_colour (a_colour)
		do
			id := an_id
			colour := a_colour
			mall := a_mall
			count := 0
		end

feature -- Access

	id: INTEGER
			-- Creature number.

	colour: INTEGER
			-- Current colour.

	count: INTEGER
			-- Meetings so far.

feature -- Basic operations

	live
			-- Meet other creatures until the mall is closed.
		local
			l_partner: INTEGER
			l_done: BOOLEAN
		do
			from
			until
				l_done
			loop
				l_partner := visit (mall)
				if l_partner = Closed then
					l_done := True
				else
					if l_partner = First then
						l_partner := collect (mall)
					end
					colour := complement (colour, l_partner)
					count := count + 1
				end
			end
		end

feature {NONE} -- Implementation

	visit (m: separate MALL): INTEGER
			-- Come to `m': `First', `Closed' or the colour of the creature met.
		do
			m.arrive (id, colour)
			Result := m.outcome_of (id)
		end

	collect (m: separate MALL): INTEGER
			-- Once a partner has met this creature waiting in `m', its colour.
		require
			has_partner: m.has_partner (id)
		do
			Result := m.partner_of (id)
			m.forget_partner (id)
		end

	mall: separate MALL
			-- Where meetings happen.

end
