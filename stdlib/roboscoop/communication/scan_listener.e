note
	description: "[
		Receives sensor_msgs/LaserScan readings as plain values: the beams' geometry and the
		ranges, in an array made on the listener's processor (its own, non-separate object).
	]"

deferred class
	SCAN_LISTENER

feature -- Basic operations

	on_scan (a_angle_min, a_angle_increment, a_range_min, a_range_max, a_timestamp: REAL_64; a_ranges: ARRAY [REAL_64])
			-- New scan: beam i (1-based in `a_ranges') points at `a_angle_min' + (i - 1) * `a_angle_increment'
			-- radians from the robot's heading (counter-clockwise); a range outside
			-- [`a_range_min', `a_range_max'] (+infinity included) means nothing was hit. `a_timestamp':
			-- the message's stamp (s).
		deferred
		end

end
