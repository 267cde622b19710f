note
	description: "A wheel with a motor."

class
	WHEEL

create
	make

feature {NONE} -- Initialization

	make
			-- Wheel at rest.
		do
			speed := 0
		end

feature -- Access

	speed: INTEGER
			-- Current speed.

feature -- Element change

	set_speed (a_speed: INTEGER)
			-- Turn at `a_speed'.
		do
			speed := a_speed
		end

end
