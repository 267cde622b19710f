note
	description: "[
		Sends the robot to the charging station whenever its battery runs low. The behaviour
		sleeps in a wait condition on the battery signaler (`await_low_battery'); when the charge
		drops below `Low_level' it stops the work (another BEHAVIOR), drives to the station
		with a NAVIGATOR, waits in another wait condition on the battery until it is charged
		(`await_charged'), then starts the work again. Its stop signaler ends it, at any of
		these stages.
	]"

class
	CHARGING_BEHAVIOUR

create
	make

feature {NONE} -- Initialization

	make (a_battery: separate BATTERY_SIGNALER; a_odometry: separate ODOMETRY_SIGNALER;
			a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE;
			a_work: separate BEHAVIOR; a_stop: separate STOP_SIGNALER)
			-- Behaviour watching `a_battery', stopping `a_work' to go charging and starting it
			-- again afterwards, until `a_stop' fires.
		do
			battery := a_battery
			work := a_work
			stop := a_stop
			create navigator.make (a_odometry, a_range, a_drive, a_stop, Period)
			create clock.make
			lowest_level := 1.0
		end

feature -- Access

	station_x, station_y, station_radius: REAL_64
			-- Where the charging station is (m).

	trips: INTEGER
			-- Trips to the station that ended with a full battery.

	lowest_level: REAL_64
			-- Lowest charge seen when leaving for the station.

	navigator: NAVIGATOR
			-- Drives the robot to the station.

feature -- Status report

	is_stopped: BOOLEAN
			-- Has the behaviour's stop signaler fired?

feature -- Element change

	set_station (a_x, a_y, a_radius: REAL_64)
			-- Place the charging station at (`a_x', `a_y'), of radius `a_radius'.
		require
			positive_radius: a_radius > 0.0
		do
			station_x := a_x
			station_y := a_y
			station_radius := a_radius
		ensure
			set: station_x = a_x and station_y = a_y and station_radius = a_radius
		end

feature -- Basic operations

	run
			-- Go charging each time the battery is low, until told to stop.
		require
			station_known: station_radius > 0.0
		do
			from
			until
				is_stopped
			loop
				await_low_battery (battery, stop)
				if not is_stopped then
					suspend_work (work)
					navigator.go_to (station_x, station_y, (station_radius / 4).min (Tolerance))
					if navigator.has_arrived then
						say ("at the station")
						await_charged (battery, stop)
					end
					if navigator.is_cancelled then
						is_stopped := True
					end
					resume_work (stop, work)
				end
			end
			say ("stopped after " + trips.out + " trip(s) to the station, lowest charge " + percent (lowest_level))
		end

feature {NONE} -- Wait conditions on the battery

	await_low_battery (a_battery: separate BATTERY_SIGNALER; a_stop: separate STOP_SIGNALER)
			-- Wait until the battery runs low (or the behaviour is stopped).
		require
			low_battery_or_stop: a_battery.is_below (Low_level) or a_stop.is_stop_requested
		do
			if a_stop.is_stop_requested then
				is_stopped := True
			else
				lowest_level := lowest_level.min (a_battery.charging_level)
				say ("battery at " + percent (a_battery.charging_level) + ", going to the station")
			end
		end

	await_charged (a_battery: separate BATTERY_SIGNALER; a_stop: separate STOP_SIGNALER)
			-- Wait at the station until the battery is charged (or the behaviour is stopped).
		require
			charged_or_stop: not a_battery.is_below (Full_level) or a_stop.is_stop_requested
		do
			if a_stop.is_stop_requested then
				is_stopped := True
			else
				trips := trips + 1
				say ("battery at " + percent (a_battery.charging_level) + ", back to work")
			end
		ensure
			one_more_trip: not is_stopped implies trips = old trips + 1
		end

feature {NONE} -- Suspending and resuming the work

	suspend_work (a_work: separate BEHAVIOR)
			-- Stop the work, and wait until its stop signaler has the request: a controller
			-- step under way is then over, and the next one sees the stop.
		do
			a_work.stop
			if attached a_work.stop_signaler as s then
				await_stop_seen (s)
			end
		ensure
			stopped: not a_work.is_running
		end

	await_stop_seen (a_stop: separate STOP_SIGNALER)
			-- Return once `a_stop' has the stop request.
		require
			requested: a_stop.is_stop_requested
		do
		end

	resume_work (a_stop: separate STOP_SIGNALER; a_work: separate BEHAVIOR)
			-- Start the work again, unless the behaviour is stopped (checked while `a_stop' is
			-- held, so a stop cannot slip in between the check and the start).
		do
			if a_stop.is_stop_requested then
				is_stopped := True
			else
				a_work.start
			end
		end

feature {NONE} -- Implementation

	battery: separate BATTERY_SIGNALER
	work: separate BEHAVIOR
	stop: separate STOP_SIGNALER
			-- The objects the behaviour coordinates.

	clock: TIMER
			-- The runtime's clock (simulated time on the simulator).

	say (a_text: STRING)
			-- Print `a_text' with the time.
		do
			print ("Charging [" + clock.now.rounded.out + " s]: " + a_text + "%N")
		end

	percent (a_level: REAL_64): STRING
			-- `a_level' (in [0, 1]) in percent.
		do
			Result := (a_level * 100).rounded.out + "%%"
		end

feature {NONE} -- Constants

	Low_level: REAL_64 = 0.2
			-- Charge under which the robot goes charging.

	Full_level: REAL_64 = 0.98
			-- Charge at which it goes back to work.

	Tolerance: REAL_64 = 0.05
			-- Largest distance (m) to the station's centre that counts as arrived.

	Period: INTEGER_64 = 100_000_000
			-- Nanoseconds between two steps of the navigator.

invariant
	trips_counted: trips >= 0
	lowest_level_in_range: 0.0 <= lowest_level and lowest_level <= 1.0

end
