note
	description: "A battery with a charge level."

class
	BATTERY

create
	make

feature {NONE} -- Initialization

	make
			-- Fully charged battery.
		do
			level := 100
		end

feature -- Access

	level: INTEGER
			-- Charge in percent.

end
