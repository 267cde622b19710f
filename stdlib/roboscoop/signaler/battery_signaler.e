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
	make, make_unconnected, make_missing

feature {NONE} -- Initialization

	make (a_topic: separate STRING)
			-- Signaler fed by the battery state published on `a_topic'.
		do
			make_unconnected
			new_subscriber (create {STRING}.make_from_separate (a_topic)).listen_battery (Current)
		end

	make_missing (a_topic, a_why: separate STRING)
			-- Signaler for a robot whose driver publishes no battery state on `a_topic' (`a_why'
			-- says which): told once on the run's error output; full, never stale, never updated,
			-- so that nothing waits on it for ever.
		local
			env: ROBOT_ENVIRONMENT
		do
			make_unconnected
			is_missing := True
			stale_after := 1.0e9
			note_reading
			create env
			env.report ("no battery topic: " + create {STRING}.make_from_separate (a_why) + " ("
				+ create {STRING}.make_from_separate (a_topic)
				+ " is not subscribed; `battery' stays full)")
		ensure
			missing: is_missing
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

	is_missing: BOOLEAN
			-- Does the robot publish no battery state (`make_missing')?

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
