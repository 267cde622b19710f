note
	description: "Keeps statistics on the readings it is sent."

class
	DATA_LOGGER

create
	make

feature {NONE} -- Initialization

	make
			-- Logger with nothing logged.
		do
			count := 0
		end

feature -- Access

	count: INTEGER
			-- Number of readings logged.

	last_value: INTEGER
			-- Value logged last.

	last_x: REAL_64
			-- Horizontal coordinate logged last.

feature -- Element change

	log (a_reading: READING)
			-- Log `a_reading'.
		do
			count := count + 1
			last_value := a_reading.value
		end

	log_value (a_value: INTEGER)
			-- Log `a_value'.
		do
			count := count + 1
			last_value := a_value
		end

	log_position (a_position: POSITION)
			-- Log where a reading was taken.
		do
			last_x := a_position.x
		end

end
