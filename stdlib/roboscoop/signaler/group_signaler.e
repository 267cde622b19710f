note
	description: "[
		Several range sensors (sensor_msgs/Range topics) seen as one signaler, such as the
		Thymio's seven proximity sensors: the latest reading of each sensor, and questions over
		the whole group (`any_below', `nearest', `nearest_sensor', `count_below'). Sensors are
		numbered from 0 in the order they were added. A reading is the distance to what the
		sensor sees (m), or negative when it sees nothing in range. The group is stale when one
		of its sensors is: each sensor has its own arrival time.
	]"

class
	GROUP_SIGNALER

inherit
	RANGE_LISTENER

	SENSOR_SIGNALER
		redefine
			is_stale
		end

create
	make, make_thymio_proximity, make_thymio_ground

feature {NONE} -- Initialization

	make
			-- Group with no sensor yet (add them with `add_range').
		do
			create readings.make (9)
			create arrivals.make (9)
			create names.make (9)
			make_sensor -- last: its postcondition asks `is_stale', which reads them
		ensure
			empty: sensor_count = 0
		end

	make_thymio_proximity (a_namespace: separate STRING)
			-- The seven proximity sensors of a Thymio under `a_namespace' ("" or "/robot1"):
			-- 0 left, 1 center_left, 2 center, 3 center_right, 4 right, 5 rear_left, 6 rear_right.
		local
			ns: STRING
		do
			make
			create ns.make_from_separate (a_namespace)
			across Proximity_names as n loop
				add_range (ns + "/proximity/" + n.item)
			end
		ensure
			seven: sensor_count = 7
		end

	make_thymio_ground (a_namespace: separate STRING)
			-- The two ground sensors of a Thymio under `a_namespace': 0 left, 1 right.
		local
			ns: STRING
		do
			make
			create ns.make_from_separate (a_namespace)
			add_range (ns + "/ground/left")
			add_range (ns + "/ground/right")
		ensure
			two: sensor_count = 2
		end

feature -- Access

	sensor_count: INTEGER
			-- Sensors in the group.
		do
			Result := readings.count
		end

	reading (a_sensor: INTEGER): REAL_64
			-- Last reading of `a_sensor' (m); negative when it sees nothing or nothing came yet.
		require
			valid_sensor: valid_sensor (a_sensor)
		do
			Result := readings [a_sensor + 1]
		end

	topic (a_sensor: INTEGER): STRING
			-- Topic of `a_sensor'.
		require
			valid_sensor: valid_sensor (a_sensor)
		do
			Result := names [a_sensor + 1]
		end

	nearest: REAL_64
			-- Smallest reading of the group; negative when no sensor sees anything.
		local
			i: INTEGER
		do
			Result := -1.0
			from i := 1 until i > readings.count loop
				if readings [i] >= 0.0 and (Result < 0.0 or readings [i] < Result) then
					Result := readings [i]
				end
				i := i + 1
			end
		end

	nearest_sensor: INTEGER
			-- Sensor with the smallest reading; -1 when no sensor sees anything.
		local
			i: INTEGER
			best: REAL_64
		do
			Result := -1
			best := -1.0
			from i := 1 until i > readings.count loop
				if readings [i] >= 0.0 and (best < 0.0 or readings [i] < best) then
					best := readings [i]
					Result := i - 1
				end
				i := i + 1
			end
		ensure
			valid: Result = -1 or else valid_sensor (Result)
		end

	count_below (a_distance: REAL_64): INTEGER
			-- Sensors seeing something closer than `a_distance'.
		do
			across readings as r loop
				if r.item >= 0.0 and r.item < a_distance then
					Result := Result + 1
				end
			end
		end

	Proximity_names: ARRAY [STRING]
			-- Topic names of the Thymio's proximity sensors, in sensor order.
		once
			Result := <<"left", "center_left", "center", "center_right", "right", "rear_left", "rear_right">>
		end

feature -- Status report

	valid_sensor (a_sensor: INTEGER): BOOLEAN
			-- Is `a_sensor' a sensor of the group?
		do
			Result := 0 <= a_sensor and a_sensor < sensor_count
		end

	any_below (a_distance: REAL_64): BOOLEAN
			-- Does some sensor see something closer than `a_distance'?
		do
			Result := count_below (a_distance) > 0
		end

	sees_anything: BOOLEAN
			-- Does some sensor see something in range?
		do
			Result := nearest >= 0.0
		end

	is_sensor_stale (a_sensor: INTEGER): BOOLEAN
			-- Has `a_sensor' been silent for longer than `stale_after' (or never spoken)?
		require
			valid_sensor: valid_sensor (a_sensor)
		do
			Result := arrivals [a_sensor + 1] < 0.0 or else clock.now - arrivals [a_sensor + 1] > stale_after
		end

	is_stale: BOOLEAN
			-- Is some sensor stale (or the group empty)?
		local
			i: INTEGER
		do
			Result := sensor_count = 0
			from i := 0 until Result or i >= sensor_count loop
				Result := is_sensor_stale (i)
				i := i + 1
			end
		end

feature -- Element change

	add_range (a_topic: separate STRING)
			-- Add the sensor publishing sensor_msgs/Range on `a_topic' (number `sensor_count').
		local
			t: STRING
		do
			create t.make_from_separate (a_topic)
			add_unconnected (t)
			new_subscriber (t).listen_range (Current, sensor_count - 1)
		ensure
			one_more: sensor_count = old sensor_count + 1
		end

	add_unconnected (a_name: separate STRING)
			-- Add a sensor fed only by calls of `on_range'.
		do
			readings.extend (-1.0)
			arrivals.extend (-1.0)
			names.extend (create {STRING}.make_from_separate (a_name))
		ensure
			one_more: sensor_count = old sensor_count + 1
		end

	on_range (a_sensor: INTEGER; a_range, a_min_range, a_max_range: REAL_64)
			-- <Precursor>
		do
			if valid_sensor (a_sensor) then
				if a_range > a_max_range or a_range < a_min_range or a_range /= a_range then
					readings [a_sensor + 1] := -1.0
				else
					readings [a_sensor + 1] := a_range
				end
				note_reading
				arrivals [a_sensor + 1] := received_at
			end
		end

feature {NONE} -- Implementation

	readings: ARRAYED_LIST [REAL_64]
			-- Last reading per sensor (negative: nothing in range).

	arrivals: ARRAYED_LIST [REAL_64]
			-- Clock reading at each sensor's last reading (negative: none yet).

	names: ARRAYED_LIST [STRING]
			-- Topic per sensor.

end
