note
	description: "A creature that goes to meetings and changes colour after each."

class
	CREATURE

create
	make

feature {NONE} -- Initialization

	make (an_id, a_colour: INTEGER; a_place: separate MEETING_PLACE)
			-- Creature `an_id' of `a_colour' going to `a_place'.
		require
			valid_colour: 1 <= a_colour and a_colour <= 3
		do
			id := an_id
			colour := a_colour
			place := a_place
		end

feature -- Access

	id: INTEGER
			-- Creature number.

	colour: INTEGER
			-- Current colour: 1 blue, 2 red, 3 yellow.

	meetings: INTEGER
			-- Meetings so far.

feature -- Basic operations

	live
			-- Go to meetings until the place closes.
		do
			from
			until
				is_done
			loop
				go_to (place)
				if not is_done then
					come_back (place)
				end
			end
			print ("Creature " + id.out + " met " + meetings.out + " others and is now " + colour_name (colour) + "%N")
		end

feature {NONE} -- Implementation

	go_to (a_place: separate MEETING_PLACE)
			-- Enter `a_place', or stop if it has closed.
		do
			if a_place.is_closed then
				is_done := True
			else
				a_place.enter (id, colour)
			end
		end

	come_back (a_place: separate MEETING_PLACE)
			-- Take the colour from the meeting in `a_place' once there was one.
		require
			met_or_closed: a_place.has_partner (id) or a_place.is_closed
		do
			if a_place.has_partner (id) then
				colour := complement (colour, a_place.partner_colour (id))
				meetings := meetings + 1
				a_place.leave (id)
			else
				is_done := True
			end
		end

	complement (a_mine, a_other: INTEGER): INTEGER
			-- Colour after a creature of `a_mine' met one of `a_other'.
		do
			if a_mine = a_other then
				Result := a_mine
			else
				Result := 6 - a_mine - a_other
			end
		ensure
			valid_colour: 1 <= Result and Result <= 3
		end

	colour_name (a_colour: INTEGER): STRING
			-- Name of `a_colour'.
		do
			inspect a_colour
			when 1 then
				Result := "blue"
			when 2 then
				Result := "red"
			else
				Result := "yellow"
			end
		end

	place: separate MEETING_PLACE
			-- Where meetings happen.

	is_done: BOOLEAN
			-- Has the place closed?

end
