note
	description: "A thermometer at a fixed position."

class
	THERMOMETER

create
	make

feature {NONE} -- Initialization

	make
			-- Thermometer at (1, 2) that read 20 degrees.
		do
			last_reading.set ("celsius", 20)
			last_value := 20
			position.set (1.0, 2.0)
		end

feature -- Access

	last_reading: READING
			-- The reading taken last.

	last_value: INTEGER
			-- Its value.

	position: POSITION
			-- Where the thermometer is.

end
