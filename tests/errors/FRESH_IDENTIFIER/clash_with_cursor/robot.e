note
	description: "A robot that answers pings."

class
	ROBOT

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER)
			-- Robot number `an_id'.
		do
			id := an_id
		end

feature -- Access

	id: INTEGER
			-- Robot number.

	pings: INTEGER
			-- Number of pings answered.

feature -- Basic operations

	ping
			-- Answer a ping.
		do
			pings := pings + 1
		end

end
