note
	description: "Two range sensors feed their readings through a bounded buffer to an obstacle detector."

class
	SENSOR_PIPELINE

create
	make

feature {NONE} -- Initialization

	make
			-- Connect the sensors and the detector through one buffer and start them.
		local
			l_buffer: separate SCAN_BUFFER
			l_left, l_right: separate RANGE_SENSOR
			l_detector: separate OBSTACLE_DETECTOR
		do
			create l_buffer.make (Capacity)
			create l_left.make ("left", l_buffer, Readings_per_sensor)
			create l_right.make ("right", l_buffer, Readings_per_sensor)
			create l_detector.make (l_buffer, 2)
			start_sensor (l_left)
			start_sensor (l_right)
			start_detector (l_detector)
		end

feature {NONE} -- Implementation

	start_sensor (a_sensor: separate RANGE_SENSOR)
			-- Let `a_sensor' publish its readings.
		do
			a_sensor.run
		end

	start_detector (a_detector: separate OBSTACLE_DETECTOR)
			-- Let `a_detector' process readings until every sensor is done.
		do
			a_detector.run
		end

	Capacity: INTEGER = 4
			-- Places in the buffer.

	Readings_per_sensor: INTEGER = 6
			-- Readings each sensor publishes.

end
