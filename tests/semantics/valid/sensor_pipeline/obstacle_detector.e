note
	description: "Takes range readings out of a buffer and reports those that are too close."

class
	OBSTACLE_DETECTOR

create
	make

feature {NONE} -- Initialization

	make (a_buffer: separate SCAN_BUFFER; a_sensor_count: INTEGER)
			-- Detector reading from `a_buffer', fed by `a_sensor_count' sensors.
		do
			buffer := a_buffer
			sensors_left := a_sensor_count
		end

feature -- Access

	obstacles: INTEGER
			-- Readings closer than `Threshold'.

feature -- Basic operations

	run
			-- Process readings until every sensor has sent its end mark.
		do
			from
			until
				sensors_left = 0
			loop
				take (buffer)
			end
			print ("Detector saw " + obstacles.out + " obstacles%N")
		end

feature {NONE} -- Implementation

	take (a_buffer: separate SCAN_BUFFER)
			-- Process the oldest reading of `a_buffer' as soon as there is one.
		require
			not_empty: not a_buffer.is_empty
		local
			l_distance: INTEGER
		do
			l_distance := a_buffer.item
			a_buffer.remove
			if l_distance < 0 then
				sensors_left := sensors_left - 1
			elseif l_distance < Threshold then
				obstacles := obstacles + 1
				print ("Obstacle at " + l_distance.out + " cm%N")
			end
		end

	buffer: separate SCAN_BUFFER
			-- Where readings come from.

	sensors_left: INTEGER
			-- Sensors that have not finished yet.

	Threshold: INTEGER = 30
			-- Distance under which a reading is an obstacle, in centimetres.

end
