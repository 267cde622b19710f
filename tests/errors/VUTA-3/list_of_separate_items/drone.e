note
	description: "A quadcopter that can take off and land."

class
	DRONE

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER)
			-- Drone number `an_id', on the ground.
		do
			id := an_id
		end

feature -- Access

	id: INTEGER
			-- Drone number.

	is_flying: BOOLEAN
			-- Is the drone in the air?

feature -- Basic operations

	take_off
			-- Leave the ground.
		do
			is_flying := True
		end

	land
			-- Come back to the ground.
		do
			is_flying := False
		end

end
