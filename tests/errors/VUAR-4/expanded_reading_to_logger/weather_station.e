note
	description: "Sends readings to a data logger."

class
	WEATHER_STATION

create
	make

feature {NONE} -- Initialization

	make
			-- Take one reading and record it.
		local
			l_logger: separate DATA_LOGGER
			r: READING
			p: POSITION
		do
			create l_logger.make
			r.set ("temperature", 21)
			p.set (2.5, 4.0)
			record (l_logger, r, p)
		end

feature -- Basic operations

	record (a_logger: separate DATA_LOGGER; a_reading: READING; a_position: POSITION)
			-- Record `a_reading', taken at `a_position', on `a_logger'.
		do
			a_logger.log (a_reading) -- E: VUAR(4)
			a_logger.log_value (a_reading.value)
			a_logger.log_position (a_position)
			show (a_reading)
		end

	show (a_reading: READING)
			-- Print `a_reading'.
		do
			print (a_reading.label + ": " + a_reading.value.out + "%N")
		end

end
