note
	description: "[
		Range sensors seen as one signaler: the Thymio's seven proximity sensors (0 left,
		1 center_left, 2 center, 3 center_right, 4 right, 5 rear_left, 6 rear_right) and two
		ground sensors (7 left, 8 right), each a sensor_msgs/Range topic.
	]"

class
	RANGE_SIGNALER

inherit
	RANGE_LISTENER

create
	make_thymio, make_unconnected

feature {NONE} -- Initialization

	make_thymio (a_namespace: separate STRING)
			-- Signaler fed by the Thymio topics under `a_namespace' ("" or "/robot1").
		local
			names: ARRAY [STRING]
			s: ROS_SUBSCRIBER
			i: INTEGER
			namespace: STRING
		do
			make_unconnected
			create namespace.make_from_separate (a_namespace)
			names := <<"proximity/left", "proximity/center_left", "proximity/center",
				"proximity/center_right", "proximity/right", "proximity/rear_left",
				"proximity/rear_right", "ground/left", "ground/right">>
			from i := 1 until i > names.count loop
				create s.make (namespace + "/" + names [i])
				s.listen_range (Current, i - 1)
				subscribers.extend (s)
				i := i + 1
			end
		end

	make_unconnected
			-- Signaler fed only by calls of `on_range'; every sensor sees nothing.
		do
			create readings.make_filled (-1.0, 0, Sensor_count - 1)
			create subscribers.make (Sensor_count)
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

	obstacle_distance: REAL_64
			-- A proximity reading closer than this is an obstacle.

	hole_distance: REAL_64
			-- A ground reading farther than this (or nothing in range) is a hole.

	update_count: INTEGER
			-- Readings received.

	Sensor_count: INTEGER = 9
			-- Sensors known.

feature -- Status report

	has_obstacle: BOOLEAN
			-- Is there an obstacle in front?
		do
			Result := is_near (0) or is_near (1) or is_near (2) or is_near (3) or is_near (4)
		end

	is_obstacle_left: BOOLEAN
			-- Is there an obstacle on the front left?
		do
			Result := is_near (0) or is_near (1)
		end

	is_obstacle_right: BOOLEAN
			-- Is there an obstacle on the front right?
		do
			Result := is_near (3) or is_near (4)
		end

	has_ground_hole: BOOLEAN
			-- Does a ground sensor see no floor?
		do
			Result := is_hole (7) or is_hole (8)
		end

feature -- Element change

	on_range (a_sensor: INTEGER; a_range, a_min_range, a_max_range: REAL_64)
			-- <Precursor>
		do
			if 0 <= a_sensor and a_sensor < Sensor_count then
				if a_range > a_max_range then
					readings [a_sensor] := -1.0
				else
					readings [a_sensor] := a_range
				end
				if a_sensor >= 7 then
					ground_seen [a_sensor - 7] := True
				end
				update_count := update_count + 1
			end
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

	ground_seen: ARRAY [BOOLEAN]
			-- Has each ground sensor reported?
		once ("OBJECT")
			create Result.make_filled (False, 0, 1)
		end

	subscribers: ARRAYED_LIST [ROS_SUBSCRIBER]
			-- One per sensor topic.

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
