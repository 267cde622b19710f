note
	description: "Colours of the chameneos and the outcomes of a visit to the mall, for the classes that inherit them."

class
	COLOURS

feature -- Colours

	Blue: INTEGER = 1
	Red: INTEGER = 2
	Yellow: INTEGER = 3
			-- The three colours.

	complement (a_mine, a_other: INTEGER): INTEGER
			-- Colour of a creature of colour `a_mine' after it met one of colour `a_other'.
		require
			valid_mine: is_colour (a_mine)
			valid_other: is_colour (a_other)
		do
			if a_mine = a_other then
				Result := a_mine
			else
				Result := Blue + Red + Yellow - a_mine - a_other
			end
		ensure
			valid_colour: is_colour (Result)
		end

	is_colour (a_value: INTEGER): BOOLEAN
			-- Is `a_value' a colour?
		do
			Result := Blue <= a_value and a_value <= Yellow
		end

feature -- Outcomes of a visit

	First: INTEGER = -1
			-- The creature came to an empty mall and waits for a partner.

	Closed: INTEGER = -2
			-- The mall is closed: every meeting has taken place.

end
