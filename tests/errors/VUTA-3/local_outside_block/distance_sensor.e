note
	description: "An infrared distance sensor on one port."

class
	DISTANCE_SENSOR

create
	make

feature {NONE} -- Initialization

	make (a_port: INTEGER)
			-- Sensor on port `a_port'.
		do
			port := a_port
			distance := 100
		end

feature -- Access

	port: INTEGER
			-- Port the sensor is plugged into.

	distance: INTEGER
			-- Last distance measured, in centimetres.

	is_calibrated: BOOLEAN
			-- Has the sensor been calibrated?

feature -- Basic operations

	calibrate
			-- Calibrate the sensor.
		do
			is_calibrated := True
			distance := distance - port
		ensure
			calibrated: is_calibrated
		end

end
