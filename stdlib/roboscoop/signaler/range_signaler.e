note
	description: "[
		Range sensors seen as one signaler that answers the questions of obstacle avoidance:
		`has_obstacle' (in front, a hole under a ground sensor included), `is_obstacle_left' /
		`is_obstacle_right', `is_obstacle_behind', `has_ground_hole'. Sensors: 0 left, 1 center_left, 2 center, 3 center_right, 4 right,
		5 rear_left, 6 rear_right, 7 ground left, 8 ground right.
		Fed either by the Thymio's seven proximity and two ground sensor_msgs/Range topics
		(`make_thymio'; distances from the body surface, obstacle under 0.08 m), or by a laser
		scanner's sensor_msgs/LaserScan (`make_laser'; each of the sensors 0..6 is the nearest
		range within a sector of beams: 0 from 45 to 75 degrees left of the heading, 1 from 15
		to 45, 2 from -15 to 15, 3 and 4 likewise on the right, 5 and 6 the rear quarters from
		105 degrees; distances from the laser, obstacle under 0.35 m; no ground sensors).
		Data is stale (`is_stale') when a connected sensor has been silent for `stale_after' s.
	]"

class
	RANGE_SIGNALER

inherit
	RANGE_LISTENER

	SCAN_LISTENER

	SENSOR_SIGNALER
		redefine
			is_stale
		end

create
	make_thymio, make_laser, make_laser_topic, make_unconnected

feature {NONE} -- Initialization

	make_thymio (a_namespace: separate STRING)
			-- Signaler fed by the Thymio topics under `a_namespace' ("" or "/robot1").
		local
			names: ARRAY [STRING]
			i: INTEGER
			namespace: STRING
		do
			make_unconnected
			create namespace.make_from_separate (a_namespace)
			names := <<"proximity/left", "proximity/center_left", "proximity/center",
				"proximity/center_right", "proximity/right", "proximity/rear_left",
				"proximity/rear_right", "ground/left", "ground/right">>
			from i := 1 until i > names.count loop
				new_subscriber (namespace + "/" + names [i]).listen_range (Current, i - 1)
				connected [i - 1] := True
				i := i + 1
			end
		end

	make_laser (a_namespace: separate STRING)
			-- Signaler fed by the laser scans on `a_namespace' + "/scan".
		local
			namespace: STRING
		do
			create namespace.make_from_separate (a_namespace)
			make_laser_topic (namespace + "/scan")
		ensure
			laser: is_laser
		end

	make_laser_topic (a_topic: separate STRING)
			-- Signaler fed by the laser scans on `a_topic' ("/robot1/scan").
		local
			i: INTEGER
		do
			make_unconnected
			is_laser := True
			obstacle_distance := 0.35
			new_subscriber (create {STRING}.make_from_separate (a_topic)).listen_scan (Current)
			from i := 0 until i > 6 loop
				connected [i] := True
				i := i + 1
			end
		ensure
			laser: is_laser
		end

	make_unconnected
			-- Signaler fed only by calls of `on_range' or `on_scan'; every sensor sees nothing.
		do
			create readings.make_filled (-1.0, 0, Sensor_count - 1)
			create arrivals.make_filled (-1.0, 0, Sensor_count - 1)
			create connected.make_filled (False, 0, Sensor_count - 1)
			create ground_seen.make_filled (False, 0, 1)
			make_sensor -- after them: its postcondition asks `is_stale', which reads them
			obstacle_distance := 0.08
			hole_distance := 0.05
		end

feature -- Access

	reading (a_sensor: INTEGER): REAL_64
			-- Last range of `a_sensor' (m); negative when nothing is in range or nothing came yet.
		require
			valid_sensor: 0 <= a_sensor and a_sensor < Sensor_count
		do
			Result := readings [a_sensor]
		end

	nearest_front: REAL_64
			-- Smallest reading of the front sensors (0..4); negative when they see nothing.
		local
			i: INTEGER
		do
			Result := -1.0
			from i := 0 until i > 4 loop
				if readings [i] >= 0.0 and (Result < 0.0 or readings [i] < Result) then
					Result := readings [i]
				end
				i := i + 1
			end
		end

	obstacle_distance: REAL_64
			-- A reading closer than this is an obstacle.

	hole_distance: REAL_64
			-- A ground reading farther than this (or nothing in range) is a hole.

	scan_count: INTEGER
			-- Laser scans received.

	Sensor_count: INTEGER = 9
			-- Sensors known.

feature -- Status report

	is_laser: BOOLEAN
			-- Is Current fed by a laser scanner?

	has_obstacle: BOOLEAN
			-- Is there an obstacle in front: something near a front sensor, or no floor under a
			-- ground sensor (a hole is in the way as much as a wall)?
		do
			Result := is_near (0) or is_near (1) or is_near (2) or is_near (3) or is_near (4) or has_ground_hole
		end

	is_obstacle_left: BOOLEAN
			-- Is there an obstacle on the front left (a hole under the left ground sensor included)?
		do
			Result := is_near (0) or is_near (1) or is_hole_left
		end

	is_obstacle_right: BOOLEAN
			-- Is there an obstacle on the front right (a hole under the right ground sensor included)?
		do
			Result := is_near (3) or is_near (4) or is_hole_right
		end

	is_obstacle_behind: BOOLEAN
			-- Is there an obstacle behind?
		do
			Result := is_near (5) or is_near (6)
		end

	has_ground_hole: BOOLEAN
			-- Does a ground sensor see no floor?
		do
			Result := is_hole (7) or is_hole (8)
		end

	is_hole_left: BOOLEAN
			-- Does the left ground sensor see no floor?
		do
			Result := is_hole (7)
		end

	is_hole_right: BOOLEAN
			-- Does the right ground sensor see no floor?
		do
			Result := is_hole (8)
		end

	is_clear: BOOLEAN
			-- Nothing in front and floor under both ground sensors?
		do
			Result := not has_obstacle and not has_ground_hole
		end

	is_sensor_stale (a_sensor: INTEGER): BOOLEAN
			-- Has `a_sensor' been silent for longer than `stale_after' (or never spoken)?
		require
			valid_sensor: 0 <= a_sensor and a_sensor < Sensor_count
		do
			Result := arrivals [a_sensor] < 0.0 or else clock.now - arrivals [a_sensor] > stale_after
		end

	is_stale: BOOLEAN
			-- Is some connected sensor stale (or, unconnected, no reading fresh)?
		local
			i: INTEGER
			any: BOOLEAN
		do
			from i := 0 until Result or i >= Sensor_count loop
				if connected [i] then
					any := True
					Result := is_sensor_stale (i)
				end
				i := i + 1
			end
			if not any then
				Result := Precursor
			end
		end

feature -- Element change

	on_range (a_sensor: INTEGER; a_range, a_min_range, a_max_range: REAL_64)
			-- <Precursor>
		do
			if 0 <= a_sensor and a_sensor < Sensor_count then
				if a_range > a_max_range or a_range /= a_range then
					readings [a_sensor] := -1.0
				else
					readings [a_sensor] := a_range
				end
				if a_sensor >= 7 then
					ground_seen [a_sensor - 7] := True
				end
				note_reading
				arrivals [a_sensor] := received_at
			end
		end

	on_scan (a_angle_min, a_angle_increment, a_range_min, a_range_max, a_timestamp: REAL_64; a_ranges: ARRAY [REAL_64])
			-- <Precursor>
		local
			i, sector: INTEGER
			angle, r, degrees: REAL_64
		do
			from sector := 0 until sector > 6 loop
				readings [sector] := -1.0
				sector := sector + 1
			end
			from i := a_ranges.lower until i > a_ranges.upper loop
				r := a_ranges [i]
				if r >= a_range_min and r <= a_range_max then
					angle := angles.normalized_angle (a_angle_min + (i - a_ranges.lower) * a_angle_increment)
					degrees := angles.degrees (angle)
					sector := sector_of (degrees)
					if sector >= 0 and then (readings [sector] < 0.0 or r < readings [sector]) then
						readings [sector] := r
					end
				end
				i := i + 1
			end
			note_reading
			from sector := 0 until sector > 6 loop
				arrivals [sector] := received_at
				sector := sector + 1
			end
			scan_count := scan_count + 1
		end

	set_distances (a_obstacle, a_hole: REAL_64)
			-- Set `obstacle_distance' and `hole_distance'.
		require
			positive: a_obstacle > 0.0 and a_hole > 0.0
		do
			obstacle_distance := a_obstacle
			hole_distance := a_hole
		end

feature {NONE} -- Implementation

	readings: ARRAY [REAL_64]
			-- Last range per sensor (negative: nothing in range).

	arrivals: ARRAY [REAL_64]
			-- Clock reading at each sensor's last reading (negative: none yet).

	connected: ARRAY [BOOLEAN]
			-- Is each sensor fed by a topic?

	ground_seen: ARRAY [BOOLEAN]
			-- Has each ground sensor reported?

	angles: ANGLE_MATH
			-- Angle helpers.
		once
			create Result
		end

	sector_of (a_degrees: REAL_64): INTEGER
			-- Laser sector (sensor 0..6) of a beam at `a_degrees' from the heading; -1 for none.
		do
			Result := -1
			if a_degrees >= -15.0 and a_degrees <= 15.0 then
				Result := 2
			elseif a_degrees > 15.0 and a_degrees <= 45.0 then
				Result := 1
			elseif a_degrees > 45.0 and a_degrees <= 75.0 then
				Result := 0
			elseif a_degrees < -15.0 and a_degrees >= -45.0 then
				Result := 3
			elseif a_degrees < -45.0 and a_degrees >= -75.0 then
				Result := 4
			elseif a_degrees >= 105.0 then
				Result := 5
			elseif a_degrees <= -105.0 then
				Result := 6
			end
		end

	is_near (a_sensor: INTEGER): BOOLEAN
			-- Does `a_sensor' see something closer than `obstacle_distance'?
		do
			Result := readings [a_sensor] >= 0.0 and readings [a_sensor] < obstacle_distance
		end

	is_hole (a_sensor: INTEGER): BOOLEAN
			-- Does ground sensor `a_sensor' see no floor?
		do
			Result := ground_seen [a_sensor - 7] and (readings [a_sensor] < 0.0 or readings [a_sensor] > hole_distance)
		end

end
