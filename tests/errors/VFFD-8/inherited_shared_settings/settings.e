note
	description: "Settings of a rover."

class
	SETTINGS

create
	make

feature {NONE} -- Initialization

	make
			-- Default settings.
		do
			max_speed := 50
		end

feature -- Access

	max_speed: INTEGER
			-- Speed limit.

end
