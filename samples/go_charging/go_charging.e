note
	description: "[
		A Thymio does its work (a behaviour: roaming the arena by default; the library's
		wandering or exploration with the argument `wander' or `explore') while a charging
		behaviour watches its battery signaler: when the charge drops below 20% it stops the
		work, drives the robot to the charging station, waits there until the battery is full
		and starts the work again. The robot, the station and the run's length come from
		ROBOT_ENVIRONMENT; a robot whose environment knows no station (a ROS 2 robot) is told
		where it is by the arguments `X Y' (metres, in the odometry frame).
	]"

class
	GO_CHARGING

inherit
	ARGUMENTS

create
	make

feature {NONE} -- Initialization

	make
			-- Create the robot (its signalers and drive), start the work and the charging behaviour;
			-- end the mission shortly before the run's duration (if it has one).
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			l_stop: separate STOP_SIGNALER
			l_work: separate BEHAVIOR
			work_name: STRING
			l_charging: separate CHARGING_BEHAVIOUR
		do
			create env
			if env.has_charging_station then
				station_x := env.station_x
				station_y := env.station_y
				station_radius := env.station_radius
			elseif argument_count >= 2 and then (argument (1).is_double and argument (2).is_double) then
				station_x := argument (1).to_double
				station_y := argument (2).to_double
				station_radius := Default_station_radius
			end
			work_name := "roam"
			if argument_count >= 1 and then (argument (argument_count).same_string ("wander")
					or argument (argument_count).same_string ("explore")) then
				work_name := argument (argument_count)
			end
			if station_radius = 0.0 then
				io.error.put_string ("go_charging: no charging station: the world has none; give its position: -- X Y%N")
			else
				create robot.make_with_limits (env.namespace, env.max_linear, env.max_angular, False)
				if work_name.same_string ("wander") then
					create {WANDER_BEHAVIOR} l_work.make (robot.range_signaler, robot.drive,
						Work_speed.min (env.max_linear), Turn_speed.min (env.max_angular))
				elseif work_name.same_string ("explore") then
					create {EXPLORATION_BEHAVIOR} l_work.make (robot.range_signaler, robot.drive,
						Work_speed.min (env.max_linear), Turn_speed.min (env.max_angular))
				else
					create {ROAMING_BEHAVIOR} l_work.make (robot.range_signaler, robot.drive,
						Work_speed.min (env.max_linear), Turn_speed.min (env.max_angular), Period, Seed)
				end
				create l_stop.make
				set_parent (l_work, l_stop)
				create l_charging.make (robot.battery, robot.odometry, robot.range_signaler, robot.drive, l_work, l_stop)
				set_station (l_charging, station_x, station_y, station_radius)
				print ("Mission: " + work_name + "; the station is at (" + station_x.out + ", " + station_y.out + ")%N")
				start_work (l_work)
				start_charging (l_charging)
				if env.duration > Mission_margin then
					(create {TIMER}.make).sleep (env.duration - Mission_margin)
					end_mission (l_stop)
				end
			end
		end

feature -- Access

	station_x, station_y, station_radius: REAL_64
			-- The charging station (m; radius 0: unknown).

feature {NONE} -- Implementation

	set_parent (a_work: separate BEHAVIOR; a_parent: separate STOP_SIGNALER)
			-- Let a stop of `a_parent' also stop `a_work'.
		do
			a_work.set_parent (a_parent)
		end

	set_station (a_charging: separate CHARGING_BEHAVIOUR; a_x, a_y, a_radius: REAL_64)
			-- Tell `a_charging' where the station is.
		do
			a_charging.set_station (a_x, a_y, a_radius)
		end

	start_work (a_work: separate BEHAVIOR)
			-- Start the work.
		do
			a_work.start
		end

	start_charging (a_charging: separate CHARGING_BEHAVIOUR)
			-- Let `a_charging' watch the battery.
		do
			a_charging.run
		end

	end_mission (a_stop: separate STOP_SIGNALER)
			-- Stop the work and the charging behaviour.
		do
			print ("Mission: over, stopping%N")
			a_stop.request_stop
		end

feature {NONE} -- Constants

	Work_speed: REAL_64 = 0.12
			-- Forward speed while wandering (m/s).

	Turn_speed: REAL_64 = 1.0
			-- Turn rate when avoiding an obstacle (rad/s).

	Period: INTEGER_64 = 100_000_000
			-- Nanoseconds between two steps of a controller.

	Seed: INTEGER = 7
			-- Seed of the roaming's random turns.

	Default_station_radius: REAL_64 = 0.2
			-- Radius of a station given by the arguments (m).

	Mission_margin: REAL_64 = 1.0
			-- Seconds before the end of the run at which the mission stops.

end
