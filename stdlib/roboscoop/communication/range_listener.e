note
	description: "Receives sensor_msgs/Range readings as plain values."

deferred class
	RANGE_LISTENER

feature -- Basic operations

	on_range (a_sensor: INTEGER; a_range, a_min_range, a_max_range: REAL_64)
			-- New reading `a_range' (m) of sensor `a_sensor', measurable in [`a_min_range', `a_max_range'].
		deferred
		end

end
