note
	description: "[
		The battery's state (sensor_msgs/BatteryState on a topic). Battery states come seldom
		(1 Hz on the simulator), so the data goes stale after 3 s without one.
	]"

class
	BATTERY_SIGNALER

inherit
	BATTERY_LISTENER

	SENSOR_SIGNALER

create
	make, make_unconnected

feature {NONE} -- Initialization

	make (a_topic: separate STRING)
			-- Signaler fed by the battery state published on `a_topic'.
		do
			make_unconnected
			new_subscriber (create {STRING}.make_from_separate (a_topic)).listen_battery (Current)
		end

	make_unconnected
			-- Signaler fed only by calls of `on_battery'; full until told otherwise.
		do
			make_sensor
			set_stale_after (3.0)
			charging_level := 1.0
		end

feature -- Access

	charging_level: REAL_64
			-- Charge, in [0, 1].

	voltage: REAL_64
			-- Last voltage (V).

feature -- Status report

	is_below (a_level: REAL_64): BOOLEAN
			-- Is the charge below `a_level'?
		do
			Result := charging_level < a_level
		end

feature -- Element change

	on_battery (a_percentage, a_voltage: REAL_64)
			-- <Precursor>
		do
			if a_percentage >= 0.0 then
				charging_level := a_percentage.min (1.0)
			end
			voltage := a_voltage
			note_reading
		end

end
