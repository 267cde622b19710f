note
	description: "Sends the robot to the charging station whenever its battery runs low."

class
	CHARGING_BEHAVIOUR

create
	make

feature {NONE} -- Initialization

	make (a_battery: separate BATTERY_SIGNALER; a_stop: separate STOP_SIGNALER)
			-- Behaviour watching `a_battery' until `a_stop' is raised.
		do
			battery := a_battery
			stop := a_stop
		end

feature -- Access

	trips: INTEGER
			-- Trips to the charging station so far.

feature -- Basic operations

	run
			-- Go charging each time the battery is low, until told to stop.
		do
			from
			until
				is_stopped
			loop
				go_charging (battery, stop)
			end
			print ("Charging: behaviour stopped after " + trips.out + " trip(s) to the station%N")
		end

feature {NONE} -- Implementation

	go_charging (a_battery: separate BATTERY_SIGNALER; a_stop: separate STOP_SIGNALER)
			-- Once the battery is low, drive to the station and charge it full; stop when told to.
		require
			low_battery_or_stop: a_battery.level < Low_level or a_stop.is_stop_requested
		do
			if a_battery.level < Low_level then
				print ("Charging: battery at " + a_battery.level.out + "%%, going to the station%N")
				from
				until
					a_battery.level = a_battery.Full
				loop
					(create {EXECUTION_ENVIRONMENT}).sleep (Charge_time)
					a_battery.recharge (Charge_step)
				end
				trips := trips + 1
				print ("Charging: battery at " + a_battery.level.out + "%%, back to work%N")
			else
				is_stopped := True
			end
		ensure
			charged_unless_stopped: not is_stopped implies a_battery.level = a_battery.Full
		end

	battery: separate BATTERY_SIGNALER
	stop: separate STOP_SIGNALER
			-- The signalers used.

	is_stopped: BOOLEAN
			-- Has the route been done?

	Low_level: INTEGER = 20
			-- Charge under which the robot goes charging, in percent.

	Charge_step: INTEGER = 30
			-- Charge gained per period at the station, in percent.

	Charge_time: INTEGER_64 = 10_000_000
			-- Charging period, in nanoseconds.

end
