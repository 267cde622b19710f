note
	description: "[
		A THYMIO_ROBOT on /robot1 (a ROS 2 run): asks its battery (the driver has no battery
		topic: reported, not waited on), sends 20 commands of 0.05 m/s 50 ms apart, prints
		"sent", then waits until the run is stopped (--duration, Ctrl-C).
	]"

class
	THYMIO_ROS2

create
	make

feature {NONE} -- Initialization

	make
			-- Drive a little, then wait.
		local
			robot: THYMIO_ROBOT
			i: INTEGER
		do
			create robot.make ("/robot1")
			print ("battery " + level (robot.battery).out + "%N")
			from i := 1 until i > 20 loop
				send (robot.drive, 0.05)
				(create {EXECUTION_ENVIRONMENT}).sleep (50_000_000)
				i := i + 1
			end
			print ("sent%N")
			from until False loop
				(create {EXECUTION_ENVIRONMENT}).sleep (100_000_000)
			end
		end

feature {NONE} -- Implementation

	level (a_battery: separate BATTERY_SIGNALER): REAL_64
			-- The battery's charge, once it has a reading.
		require
			a_battery.has_reading
		do
			Result := a_battery.charging_level
		end

	send (a_drive: separate DIFFERENTIAL_DRIVE; a_speed: REAL_64)
			-- Command `a_speed' forward.
		do
			a_drive.send (a_speed, 0.0)
		end

end
