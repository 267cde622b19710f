note
	description: "A simulated range sensor publishing distances, then an end-of-stream mark."

class
	RANGE_SENSOR

create
	make

feature {NONE} -- Initialization

	make (a_name: separate STRING; a_buffer: separate SCAN_BUFFER; a_count: INTEGER)
			-- Sensor `a_name' that will publish `a_count' readings into `a_buffer'.
		do
			create name.make_from_separate (a_name)
			buffer := a_buffer
			reading_count := a_count
		end

feature -- Access

	name: STRING
			-- Where the sensor is mounted.

	reading_count: INTEGER
			-- Readings to publish.

feature -- Basic operations

	run
			-- Publish every reading, then the end mark.
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > reading_count
			loop
				publish (buffer, simulated_distance (i))
				i := i + 1
			end
			publish (buffer, End_mark)
			print ("Sensor " + name + " is done%N")
		end

feature {NONE} -- Implementation

	publish (a_buffer: separate SCAN_BUFFER; a_distance: INTEGER)
			-- Put `a_distance' into `a_buffer' as soon as it has room.
		require
			room: not a_buffer.is_full
		do
			a_buffer.put (a_distance)
		ensure
			published: a_buffer.count = old a_buffer.count + 1
		end

	simulated_distance (i: INTEGER): INTEGER
			-- A made-up distance for the `i'-th reading, in centimetres.
		do
			Result := (i * 37 + name.count * 11) \\ 120
		ensure
			in_range: 0 <= Result and Result < 120
		end

	buffer: separate SCAN_BUFFER
			-- Where readings go.

	End_mark: INTEGER = -1
			-- Reading that tells the detector this sensor is done.

end
