note
	description: "[
		The robot's laser scanner (sensor_msgs/LaserScan on a topic): the latest scan, updated by
		the transport through asynchronous calls on this signaler's processor. Beams are numbered
		from 1; beam i points at `angle (i)' radians from the robot's heading (counter-clockwise).
		A beam that hit nothing (a reading outside [range_min, range_max], +infinity in ROS) reads
		`No_hit' (+infinity). Besides the ranges it answers the queries of obstacle avoidance
		(`range_at', `min_range_in', `is_corridor_clear') and the obstacle segments of a local
		tangent graph: beams of one continuous obstacle share a segment number, and the endpoints
		(`endpoint_beam', `endpoint_side') are where an obstacle ends: at a discontinuity of the
		ranges larger than `discontinuity' or next to a beam that hit nothing. A controller on
		another processor can take a local copy (`make_copy' / `copy_scan') and query it without
		reserving the signaler.
	]"

class
	LASER_SIGNALER

inherit
	SENSOR_SIGNALER

	SCAN_LISTENER

	ANGLE_MATH

create
	make, make_unconnected, make_copy

feature {NONE} -- Initialization

	make (a_topic: separate STRING)
			-- Signaler fed by the scans published on `a_topic' ("/scan", "/robot1/scan").
		do
			make_unconnected
			new_subscriber (create {STRING}.make_from_separate (a_topic)).listen_scan (Current)
		end

	make_unconnected
			-- Signaler fed only by calls of `on_scan'; no scan yet.
		do
			make_sensor
			create readings.make_empty
			create segments.make_empty
			create endpoint_beams.make (8)
			create endpoint_sides.make (8)
			discontinuity := Default_discontinuity
		ensure
			no_scan: beam_count = 0
		end

	make_copy (a_other: separate LASER_SIGNALER)
			-- Unconnected signaler holding a copy of `a_other''s latest scan.
		do
			make_unconnected
			copy_scan (a_other)
		end

feature -- Access

	angle_min: REAL_64
			-- Angle of beam 1 (rad, from the heading).

	angle_increment: REAL_64
			-- Angle between neighbouring beams (rad).

	range_min, range_max: REAL_64
			-- Measurable ranges (m).

	timestamp: REAL_64
			-- Stamp of the last scan (s).

	discontinuity: REAL_64
			-- Jump between neighbouring ranges (m) that separates two obstacles.

	Default_discontinuity: REAL_64 = 0.25
			-- Default `discontinuity'.

	No_hit: REAL_64
			-- Range of a beam that hit nothing.
		once
			Result := {REAL_64}.positive_infinity
		end

	beam_count: INTEGER
			-- Beams of the last scan.
		do
			Result := readings.count
		end

	range (i: INTEGER): REAL_64
			-- Range of beam `i' (m), `No_hit' when it hit nothing.
		require
			valid_beam: 1 <= i and i <= beam_count
		do
			Result := readings [i]
		end

	angle (i: INTEGER): REAL_64
			-- Direction of beam `i' (rad from the heading, in (-pi, pi]).
		require
			valid_beam: 1 <= i and i <= beam_count
		do
			Result := normalized_angle (angle_min + (i - 1) * angle_increment)
		end

	beam_at (a_angle: REAL_64): INTEGER
			-- The beam closest to direction `a_angle' (rad from the heading); 0 when outside the field of view.
		local
			k: INTEGER
			offset: REAL_64
		do
			if beam_count > 0 and angle_increment > 0.0 then
				offset := a_angle - angle_min
				if is_full_circle then
					offset := offset - 2.0 * Pi * (offset / (2.0 * Pi)).floor
				end
				k := (offset / angle_increment).rounded
				if is_full_circle then
					k := k \\ beam_count
				end
				if 0 <= k and k < beam_count then
					Result := k + 1
				end
			end
		ensure
			valid: 0 <= Result and Result <= beam_count
		end

	range_at (a_angle: REAL_64): REAL_64
			-- Range seen in direction `a_angle' (the closest beam's); `No_hit' outside the field of view.
		local
			i: INTEGER
		do
			i := beam_at (a_angle)
			if i > 0 then
				Result := readings [i]
			else
				Result := No_hit
			end
		end

	min_range_in (a_from, a_to: REAL_64): REAL_64
			-- Smallest range over the sector swept counter-clockwise from `a_from' to `a_to' (rad from the heading).
		local
			i, first, steps, n: INTEGER
			width: REAL_64
		do
			Result := No_hit
			n := beam_count
			if n > 0 and angle_increment > 0.0 then
				width := a_to - a_from
				width := width - 2.0 * Pi * (width / (2.0 * Pi)).floor
				first := beam_at (a_from)
				steps := (width / angle_increment).rounded
				if first = 0 then
					first := 1
				end
				from i := 0 until i > steps or i >= n loop
					Result := Result.min (readings [(first - 1 + i) \\ n + 1])
					i := i + 1
				end
			end
		end

	clear_length (a_angle, a_half_width, a_max: REAL_64): REAL_64
			-- How far (at most `a_max' m) a disc of radius `a_half_width' centred on the robot can move
			-- in direction `a_angle' (rad from the heading) before touching a hit point (points
			-- already within `a_half_width' block only if ahead).
		require
			non_negative: a_half_width >= 0.0 and a_max >= 0.0
		local
			i: INTEGER
			r, a, along, across_distance, reach: REAL_64
		do
			Result := a_max
			from i := 1 until i > beam_count loop
				r := readings [i]
				if r <= Result + a_half_width then
					a := angle_min + (i - 1) * angle_increment - a_angle
					along := r * cosine (a)
					across_distance := (r * sine (a)).abs
					if along > 0.0 and across_distance < a_half_width then
							-- Moving forward brings the disc closer to this point (never to one behind).
						reach := sqrt (a_half_width * a_half_width - across_distance * across_distance)
						Result := Result.min ((along - reach).max (0.0))
					end
				end
				i := i + 1
			end
		ensure
			bounded: 0.0 <= Result and Result <= a_max
		end

	nearest_in (a_from, a_to: REAL_64): INTEGER
			-- Beam with the smallest range in the sector swept counter-clockwise from `a_from' to `a_to'
			-- (0 when nothing there was hit).
		local
			i, k, first, steps, n: INTEGER
			width, best: REAL_64
		do
			n := beam_count
			if n > 0 and angle_increment > 0.0 then
				best := No_hit
				width := a_to - a_from
				width := width - 2.0 * Pi * (width / (2.0 * Pi)).floor
				first := beam_at (a_from)
				steps := (width / angle_increment).rounded
				if first = 0 then
					first := 1
				end
				from i := 0 until i > steps or i >= n loop
					k := (first - 1 + i) \\ n + 1
					if readings [k] < best then
						best := readings [k]
						Result := k
					end
					i := i + 1
				end
			end
		ensure
			valid: 0 <= Result and Result <= beam_count
		end

	nearest_beam: INTEGER
			-- Beam with the smallest range (0 when none hit anything).
		local
			i: INTEGER
			best: REAL_64
		do
			best := No_hit
			from i := 1 until i > beam_count loop
				if readings [i] < best then
					best := readings [i]
					Result := i
				end
				i := i + 1
			end
		end

	nearest_range: REAL_64
			-- Smallest range of the scan (`No_hit' when nothing was hit).
		local
			i: INTEGER
		do
			i := nearest_beam
			if i > 0 then
				Result := readings [i]
			else
				Result := No_hit
			end
		end

feature -- Obstacle segments

	segment (i: INTEGER): INTEGER
			-- Obstacle segment of beam `i' (0 when it hit nothing); beams of one continuous obstacle share it.
		require
			valid_beam: 1 <= i and i <= beam_count
		do
			Result := segments [i]
		end

	segment_count: INTEGER
			-- Obstacle segments of the last scan.

	endpoint_count: INTEGER
			-- Endpoints of obstacle segments (where an obstacle ends as seen from the robot).
		do
			Result := endpoint_beams.count
		end

	endpoint_beam (k: INTEGER): INTEGER
			-- Beam of the `k'-th endpoint: the last beam of its obstacle before free space or a farther one.
		require
			valid_endpoint: 1 <= k and k <= endpoint_count
		do
			Result := endpoint_beams [k]
		end

	endpoint_side (k: INTEGER): INTEGER
			-- Side of the `k'-th endpoint on which the way is open: 1 counter-clockwise, -1 clockwise.
		require
			valid_endpoint: 1 <= k and k <= endpoint_count
		do
			Result := endpoint_sides [k]
		end

feature -- Status report

	is_hit (r: REAL_64): BOOLEAN
			-- Is `r' the range of a beam that hit something?
		do
			Result := r <= range_max
		end

	is_full_circle: BOOLEAN
			-- Do the beams cover the whole circle (beam 1 follows the last one)?
		do
			Result := beam_count > 1 and then beam_count * angle_increment >= 2.0 * Pi - angle_increment / 2.0
		end

	is_corridor_clear (a_angle, a_length, a_half_width: REAL_64): BOOLEAN
			-- Can a disc of radius `a_half_width' move `a_length' metres from the robot in direction
			-- `a_angle' (rad from the heading) without touching a hit point?
		require
			non_negative: a_length >= 0.0 and a_half_width >= 0.0
		do
			Result := clear_length (a_angle, a_half_width, a_length) >= a_length
		end

	has_obstacle_within (a_distance, a_from, a_to: REAL_64): BOOLEAN
			-- Is something closer than `a_distance' in the sector from `a_from' to `a_to' (counter-clockwise)?
		do
			Result := min_range_in (a_from, a_to) < a_distance
		end

feature -- Element change

	on_scan (a_angle_min, a_angle_increment, a_range_min, a_range_max, a_timestamp: REAL_64; a_ranges: ARRAY [REAL_64])
			-- <Precursor>
		local
			i: INTEGER
			r: REAL_64
		do
			angle_min := a_angle_min
			angle_increment := a_angle_increment
			range_min := a_range_min
			range_max := a_range_max
			timestamp := a_timestamp
			create readings.make_filled (No_hit, 1, a_ranges.count)
			from i := 1 until i > a_ranges.count loop
				r := a_ranges [a_ranges.lower + i - 1]
				if not r.is_nan and then r >= a_range_min and then r <= a_range_max then
					readings [i] := r
				end
				i := i + 1
			end
			find_segments
			note_reading
		ensure then
			beams: beam_count = a_ranges.count
		end

	copy_scan (a_other: separate LASER_SIGNALER)
			-- Take `a_other''s latest scan (its ranges copied beam by beam).
		local
			i, n: INTEGER
		do
			n := a_other.beam_count
			angle_min := a_other.angle_min
			angle_increment := a_other.angle_increment
			range_min := a_other.range_min
			range_max := a_other.range_max
			timestamp := a_other.timestamp
			discontinuity := a_other.discontinuity
			create readings.make_filled (No_hit, 1, n)
			from i := 1 until i > n loop
				readings [i] := a_other.range (i)
				i := i + 1
			end
			find_segments
			note_reading
		ensure
			same_beams: beam_count = a_other.beam_count
		end

	set_discontinuity (a_jump: REAL_64)
			-- Set `discontinuity'.
		require
			positive: a_jump > 0.0
		do
			discontinuity := a_jump
			find_segments
		ensure
			set: discontinuity = a_jump
		end

feature {NONE} -- Implementation

	readings: ARRAY [REAL_64]
			-- Ranges of the last scan (`No_hit' for beams that hit nothing).

	segments: ARRAY [INTEGER]
			-- Obstacle segment per beam (0: no hit).

	endpoint_beams, endpoint_sides: ARRAYED_LIST [INTEGER]
			-- Endpoints: beam and open side.

	is_continuous (r1, r2: REAL_64): BOOLEAN
			-- Do two neighbouring ranges belong to one obstacle?
		do
			Result := is_hit (r1) and is_hit (r2) and (r1 - r2).abs <= discontinuity
		end

	find_segments
			-- Number the obstacle segments and find their endpoints.
		local
			i, j, n, last_id: INTEGER
			ri, rj: REAL_64
		do
			n := beam_count
			create segments.make_filled (0, 1, n.max (1))
			endpoint_beams.wipe_out
			endpoint_sides.wipe_out
			segment_count := 0
			from i := 1 until i > n loop
				if is_hit (readings [i]) then
					if i > 1 and then is_continuous (readings [i - 1], readings [i]) then
						segments [i] := segments [i - 1]
					else
						segment_count := segment_count + 1
						segments [i] := segment_count
					end
				end
				i := i + 1
			end
			if is_full_circle and then segments [n] > 0 and then segments [1] > 0
				and then segments [n] /= segments [1] and then is_continuous (readings [n], readings [1])
			then
					-- The last segment goes on with the first one: renumber it.
				last_id := segments [n]
				from i := n until i < 1 or else segments [i] /= last_id loop
					segments [i] := segments [1]
					i := i - 1
				end
				segment_count := segment_count - 1
			end
			from i := 1 until i > n loop
				if i < n then
					j := i + 1
				else
					j := 1
				end
				if i < n or is_full_circle then
					ri := readings [i]
					rj := readings [j]
					if is_hit (ri) and not is_continuous (ri, rj) and ri <= rj then
						add_endpoint (i, 1)
					elseif is_hit (rj) and not is_continuous (ri, rj) and rj < ri then
						add_endpoint (j, -1)
					end
				end
				i := i + 1
			end
		end

	add_endpoint (a_beam, a_side: INTEGER)
			-- Record an endpoint.
		do
			endpoint_beams.extend (a_beam)
			endpoint_sides.extend (a_side)
		end

end
