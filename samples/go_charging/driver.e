note
	description: "Drives the robot along a route, leg by leg; each leg drains the battery."

class
	DRIVER

create
	make

feature {NONE} -- Initialization

	make (a_battery: separate BATTERY_SIGNALER; a_stop: separate STOP_SIGNALER; a_legs: INTEGER)
			-- Driver that will drive `a_legs' legs on `a_battery', then raise `a_stop'.
		require
			some_legs: a_legs > 0
		do
			battery := a_battery
			stop := a_stop
			leg_count := a_legs
		end

feature -- Access

	leg_count: INTEGER
			-- Legs of the route.

	legs_driven: INTEGER
			-- Legs driven so far.

feature -- Basic operations

	drive
			-- Drive the whole route, then tell the other behaviours to stop.
		do
			from
			until
				legs_driven = leg_count
			loop
				drive_leg (battery)
				(create {EXECUTION_ENVIRONMENT}).sleep (Leg_time)
			end
			finish (stop)
		end

feature {NONE} -- Implementation

	drive_leg (a_battery: separate BATTERY_SIGNALER)
			-- Drive the next leg, as soon as the battery has enough charge for it.
		require
			enough_charge: a_battery.level >= Leg_cost
		do
			a_battery.drain (Leg_cost)
			legs_driven := legs_driven + 1
			print ("Driver: leg " + legs_driven.out + " driven, battery at " + a_battery.level.out + "%%%N")
		ensure
			one_more_leg: legs_driven = old legs_driven + 1
		end

	finish (a_stop: separate STOP_SIGNALER)
			-- Tell the other behaviours the route is done.
		do
			a_stop.request_stop
			print ("Driver: route done%N")
		end

	battery: separate BATTERY_SIGNALER
	stop: separate STOP_SIGNALER
			-- The signalers used.

	Leg_cost: INTEGER = 15
			-- Charge one leg takes, in percent.

	Leg_time: INTEGER_64 = 5_000_000
			-- Time to drive one leg, in nanoseconds.

invariant
	not_too_far: legs_driven <= leg_count

end
