note
	description: "[
		Exercise 1's reference solution (exercises/1_signaler): the state of a temperature sensor.
	]"

class
	TEMPERATURE_SIGNALER

create
	make

feature {NONE} -- Initialization

	make (a_limit: REAL_64)
			-- A signaler with no reading yet, overheated above `a_limit' degrees Celsius.
		do
			limit := a_limit
		ensure
			limit_set: limit = a_limit
			no_reading: not has_reading
		end

feature -- Access

	limit: REAL_64
			-- Above this temperature (Celsius) the sensor is overheated.

	celsius: REAL_64
			-- The latest reading.
		require
			has_reading: has_reading
		do
			Result := latest
		end

	maximum: REAL_64
			-- The highest reading so far.
		require
			has_reading: has_reading
		do
			Result := highest
		end

	average: REAL_64
			-- The mean of the readings so far.
		require
			has_reading: has_reading
		do
			Result := sum / reading_count
		end

	reading_count: INTEGER
			-- Readings received.

feature -- Status report

	has_reading: BOOLEAN
			-- Has a reading come?
		do
			Result := reading_count > 0
		end

	is_overheated: BOOLEAN
			-- Is the latest reading above `limit'? (False before the first reading.)
		do
			Result := has_reading and then latest > limit
		end

feature -- Element change

	update (a_celsius: REAL_64)
			-- Take a new reading.
		do
			if not has_reading or else a_celsius > highest then
				highest := a_celsius
			end
			latest := a_celsius
			sum := sum + a_celsius
			reading_count := reading_count + 1
		ensure
			counted: reading_count = old reading_count + 1
			latest: celsius = a_celsius
			highest: maximum >= a_celsius
		end

feature {NONE} -- Implementation

	latest, highest, sum: REAL_64
			-- The latest and the highest reading, and the sum of all.

invariant
	readings_not_negative: reading_count >= 0

end
