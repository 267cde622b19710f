note
	description: "Receives sensor_msgs/BatteryState readings as plain values."

deferred class
	BATTERY_LISTENER

feature -- Basic operations

	on_battery (a_percentage, a_voltage: REAL_64)
			-- New reading: charge in [0, 1] (negative: unknown), voltage (V).
		deferred
		end

end
