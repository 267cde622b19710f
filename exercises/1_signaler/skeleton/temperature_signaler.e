note
	description: "[
		The state of a temperature sensor (exercise 1, README.md): the latest reading, the
		highest, the mean, and whether the sensor is above its limit. Its listener calls
		`update' with each reading; controllers read the queries in their wait conditions.
		Complete the features marked TODO.
	]"

class
	TEMPERATURE_SIGNALER

create
	make

feature {NONE} -- Initialization

	make (a_limit: REAL_64)
			-- A signaler with no reading yet, overheated above `a_limit' degrees Celsius.
		do
			-- TODO
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
			-- TODO
		end

	maximum: REAL_64
			-- The highest reading so far.
		require
			has_reading: has_reading
		do
			-- TODO
		end

	average: REAL_64
			-- The mean of the readings so far.
		require
			has_reading: has_reading
		do
			-- TODO
		end

	reading_count: INTEGER
			-- Readings received.

feature -- Status report

	has_reading: BOOLEAN
			-- Has a reading come?
		do
			-- TODO
		end

	is_overheated: BOOLEAN
			-- Is the latest reading above `limit'? (False before the first reading.)
		do
			-- TODO
		end

feature -- Element change

	update (a_celsius: REAL_64)
			-- Take a new reading.
		do
			-- TODO
		ensure
			counted: reading_count = old reading_count + 1
		end

end
