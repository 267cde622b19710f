note
	description: "Calibrates a distance sensor and reads it."

class
	SENSOR_CHECK

create
	make

feature {NONE} -- Initialization

	make
			-- Create the sensor, calibrate it and print a reading.
		local
			l_sensor: separate DISTANCE_SENSOR
		do
			create l_sensor.make (3)
			l_sensor.calibrate -- E: VUTA(3)
			separate l_sensor as s do
				s.calibrate
				print ("distance: " + s.distance.out + "%N")
			end
			print (l_sensor.distance) -- E: VUTA(3)
		end

end
