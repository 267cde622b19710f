note
	description: "Sends five readings to a temperature signaler, as a sensor's listener would."

class
	FEEDER

feature -- Basic operations

	feed (s: separate TEMPERATURE_SIGNALER)
			-- Send 31, 33, 36, 35 and 34 degrees, a little apart.
		local
			readings: ARRAY [REAL_64]
			i: INTEGER
		do
			readings := <<31.0, 33.0, 36.0, 35.0, 34.0>>
			from i := 1 until i > readings.count loop
				(create {EXECUTION_ENVIRONMENT}).sleep (1_000_000)
				send (s, readings [i])
				i := i + 1
			end
		end

feature {NONE} -- Implementation

	send (s: separate TEMPERATURE_SIGNALER; a_celsius: REAL_64)
		do
			s.update (a_celsius)
		end

end
