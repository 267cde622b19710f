note
	description: "[
		A robot drives a route while a behaviour watches its battery signaler and sends it
		charging whenever the level drops under 20%; the driver waits while the battery is too
		low for the next leg.
	]"

class
	GO_CHARGING

create
	make

feature {NONE} -- Initialization

	make
			-- Create the signalers, start the driver and the charging behaviour, then report.
		local
			l_battery: separate BATTERY_SIGNALER
			l_stop: separate STOP_SIGNALER
			l_driver: separate DRIVER
			l_charging: separate CHARGING_BEHAVIOUR
		do
			create l_battery.make
			create l_stop.make
			create l_driver.make (l_battery, l_stop, Leg_count)
			create l_charging.make (l_battery, l_stop)
			start_charging (l_charging)
			start_driver (l_driver)
			report (l_battery, l_stop)
		end

feature {NONE} -- Implementation

	start_charging (a_charging: separate CHARGING_BEHAVIOUR)
			-- Let `a_charging' watch the battery.
		do
			a_charging.run
		end

	start_driver (a_driver: separate DRIVER)
			-- Let `a_driver' drive the route.
		do
			a_driver.drive
		end

	report (a_battery: separate BATTERY_SIGNALER; a_stop: separate STOP_SIGNALER)
			-- Once the route is done, tell how the battery fared.
		require
			route_done: a_stop.is_stop_requested
		do
			print ("Route of " + Leg_count.out + " legs done: battery at " + a_battery.level.out + "%%, recharged " + a_battery.charge_count.out + " time(s)%N")
		end

	Leg_count: INTEGER = 8
			-- Legs of the route.

end
