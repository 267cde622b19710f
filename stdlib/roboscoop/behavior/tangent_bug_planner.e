note
	description: "[
		The geometry and the decisions of TangentBug (Kamon, Rivlin, Rimon 1998) for a disc
		robot with a laser of limited range; no SCOOP here: `update' takes the robot's pose and
		a local copy of the latest scan, plans again on each new scan (in the pose taken as the
		scan's) and sets the command (`linear', `angular', never into an obstacle) and `mode'.

		Motion to goal: the nodes of the local tangent graph are the goal, when the way to it
		is clear within the laser's range, and the endpoints of the obstacle segments seen
		(offset sideways by the robot's clearance, reachable in a straight line, and closer to
		the goal than the robot). The robot heads for the node O that minimises the heuristic
		distance d(x, O) + d(O, goal); at a local minimum (no node, the distance grows by more
		than `Heuristic_slack' twice running, or no longer shrinks for `Stall_plans' plans)
		boundary following begins, going on round the obstacle past the last node.

		Boundary following: the robot keeps the followed boundary (the nearest point on the
		followed side, kept on one boundary from plan to plan) at `follow_distance'.
		`d_followed' is the smallest distance to the goal of the points sensed on the followed
		obstacle since boundary following began; `d_reach' is the smallest distance to the goal
		of the free points the robot can reach in a straight line now (the nodes, and the clear
		part of the ray towards the goal). The robot leaves when d_reach < d_followed -
		`Leave_slack', heads for that point, then goes on in motion to goal. Coming back to where
		it first was beside the boundary, after going round (`Loop_away' away from it), means
		the obstacle encloses the goal or the robot: the goal is unreachable.
	]"

class
	TANGENT_BUG_PLANNER

inherit
	ANGLE_MATH

create
	make

feature {NONE} -- Initialization

	make (a_goal_x, a_goal_y, a_radius, a_max_linear, a_max_angular: REAL_64)
			-- Planner towards (`a_goal_x', `a_goal_y') for a robot of radius `a_radius' driven at most
			-- at `a_max_linear' m/s and `a_max_angular' rad/s.
		require
			positive: a_radius > 0.0 and a_max_linear > 0.0 and a_max_angular > 0.0
		do
			goal_x := a_goal_x
			goal_y := a_goal_y
			radius := a_radius
			max_linear := a_max_linear
			max_angular := a_max_angular
			margin := 0.12
			tolerance := 0.15
			cruise_speed := a_max_linear.min (0.4)
			follow_speed := a_max_linear.min (0.3)
			follow_distance := a_radius + 0.25
			mode := Motion_to_goal
			best_heuristic := Infinity
			progress_reference := Infinity
			d_followed := Infinity
			d_reach := Infinity
		ensure
			moving_to_goal: mode = Motion_to_goal
		end

feature -- Access

	goal_x, goal_y: REAL_64
			-- The goal.

	radius: REAL_64
			-- The robot's radius (m).

	margin: REAL_64
			-- Clearance kept from obstacles beyond `radius' when passing them (m).

	tolerance: REAL_64
			-- Distance to the goal that counts as reached (m).

	max_linear, max_angular: REAL_64
			-- Speed limits.

	cruise_speed, follow_speed: REAL_64
			-- Forward speeds in motion to goal and in boundary following (m/s).

	follow_distance: REAL_64
			-- Distance kept from the followed obstacle, centre to boundary (m).

	mode: INTEGER
			-- Current mode (the constants of NAVIGATION_SIGNALER).

	linear, angular: REAL_64
			-- Command computed by the last `update'.

	distance_to_goal: REAL_64
			-- At the last `update'.

	path_length: REAL_64
			-- Distance travelled (sum of the moves between updates).

	best_heuristic: REAL_64
			-- Smallest heuristic distance of this motion-to-goal phase.

	d_followed: REAL_64
			-- Smallest distance to the goal sensed on the followed obstacle.

	d_reach: REAL_64
			-- Smallest distance to the goal of a free point reachable now.

	follow_side: INTEGER
			-- Side of the followed obstacle: 1 left, -1 right.

	hit_x, hit_y: REAL_64
			-- Where the robot first was beside the followed boundary (valid when `has_hit').

	has_hit: BOOLEAN
			-- Has the robot been beside the followed boundary since boundary following began?

	boundary_count, leave_count: INTEGER
			-- Times boundary following began, and ended by the leave condition.

	Heuristic_slack: REAL_64 = 0.12
			-- Growth of the heuristic distance that ends motion to goal (m).

	Progress_step: REAL_64 = 0.05
			-- Decrease of the heuristic distance that counts as progress (m).

	Stall_plans: INTEGER = 30
			-- Plans (scans) without progress that end motion to goal: 3 s at 10 Hz.

	Transit_reached: REAL_64 = 0.15
			-- Distance to the transit point that ends the transit (m).

	Leave_slack: REAL_64 = 0.05
			-- How much closer than `d_followed' a reachable point must be to leave (m).

	Continuity: REAL_64 = 0.5
			-- Largest move of the followed point between two plans that keeps it on the same boundary (m).

	Loop_away: REAL_64 = 0.6
			-- Distance from the hit point the robot must have gone before a return counts as a loop (m).

	Loop_back: REAL_64 = 0.35
			-- Distance to the hit point that closes the loop (m).

	Motion_to_goal: INTEGER = 2
	Boundary_following: INTEGER = 3
	Goal_reached: INTEGER = 4
	Goal_unreachable: INTEGER = 5
			-- Modes (as NAVIGATION_SIGNALER numbers them).

feature -- Status report

	is_finished: BOOLEAN
			-- Reached or unreachable?
		do
			Result := mode = Goal_reached or mode = Goal_unreachable
		end

feature -- Element change

	set_speeds (a_cruise, a_follow: REAL_64)
			-- Set `cruise_speed' and `follow_speed' (within `max_linear').
		require
			positive: a_cruise > 0.0 and a_follow > 0.0
		do
			cruise_speed := a_cruise.min (max_linear)
			follow_speed := a_follow.min (max_linear)
		end

	set_tolerance (a_tolerance: REAL_64)
			-- Set `tolerance'.
		require
			positive: a_tolerance > 0.0
		do
			tolerance := a_tolerance
		end

feature -- Basic operations

	update (a_x, a_y, a_theta: REAL_64; a_scan: LASER_SIGNALER; a_new_scan: BOOLEAN)
			-- Decide the command for the robot at (`a_x', `a_y') heading `a_theta', with `a_scan' the
			-- latest scan; plan again when `a_new_scan' (the pose is then taken as the scan's).
		local
			step: REAL_64
		do
			if has_pose then
				step := distance (x, y, a_x, a_y)
				path_length := path_length + step
				follow_travel := follow_travel + step
			end
			x := a_x
			y := a_y
			theta := a_theta
			has_pose := True
			distance_to_goal := distance (x, y, goal_x, goal_y)
			linear := 0.0
			angular := 0.0
			if is_finished then
					-- Stay stopped.
			elseif distance_to_goal <= tolerance then
				mode := Goal_reached
			elseif a_scan.beam_count > 0 then
				if a_new_scan or not has_plan then
					scan_x := x
					scan_y := y
					scan_theta := theta
					has_plan := True
					goal_angle := normalized_angle (arc_tangent_2 (goal_y - y, goal_x - x) - theta)
					find_nodes (a_scan)
					if mode = Boundary_following then
						follow_boundary (a_scan)
					else
						move_to_goal (a_scan)
					end
				end
				if not is_finished then
					drive_towards (a_scan)
				end
			end
		ensure
			stopped_when_finished: is_finished implies (linear = 0.0 and angular = 0.0)
		end

	drive_towards (a_scan: LASER_SIGNALER)
			-- Turn towards `target_heading' and drive at up to `target_speed' when facing it, never
			-- into an obstacle of `a_scan' (seen from where it was taken).
		local
			error, front: REAL_64
		do
			error := normalized_angle (target_heading - theta)
			angular := (3.0 * error).max (- max_angular).min (max_angular)
			if error.abs < 1.2 then
				linear := target_speed * cosine (error) ^ 2
			end
			front := a_scan.clear_length (normalized_angle (theta - scan_theta), radius + 0.015, 0.6)
				- distance (x, y, scan_x, scan_y)
			if front < 0.6 then
				linear := linear.min (0.8 * front)
			end
			linear := linear.max (0.0).min (max_linear)
		end

feature {NONE} -- Motion to goal

	move_to_goal (a_scan: LASER_SIGNALER)
			-- Head for the best node, or begin boundary following at a local minimum. Just after
			-- leaving a boundary, first head for the point that allowed it (`transit_x', `transit_y').
		local
			h: REAL_64
		do
			plan_count := plan_count + 1
			if is_in_transit and then (goal_free or distance (x, y, transit_x, transit_y) < Transit_reached
				or distance_to_goal < transit_limit)
			then
				is_in_transit := False
				best_heuristic := Infinity
				progress_reference := Infinity
				progress_plan := plan_count
			end
			if is_in_transit then
				h := distance (x, y, transit_x, transit_y)
				if h < transit_best - Progress_step then
					transit_best := h
					progress_plan := plan_count
				end
				steered_side := 0
				if plan_count - progress_plan > Stall_plans then
					is_in_transit := False
					begin_following (a_scan)
				else
					steer (normalized_angle (arc_tangent_2 (transit_y - y, transit_x - x) - theta), cruise_speed)
				end
			else
				if goal_free then
					h := distance_to_goal
					node_angle := goal_angle
				elseif has_node then
					h := node_heuristic
				else
					h := Infinity
				end
				if h < progress_reference - Progress_step then
					progress_reference := h
					progress_plan := plan_count
				end
				if h > best_heuristic + Heuristic_slack then
					rise_count := rise_count + 1
				else
					rise_count := 0
				end
				if rise_count >= 2 or not (goal_free or has_node) or plan_count - progress_plan > Stall_plans then
						-- A local minimum of the heuristic distance: it grows, or no longer shrinks.
					begin_following (a_scan)
				else
					best_heuristic := best_heuristic.min (h)
					if goal_free then
						steered_side := 0
					else
						steered_side := node_side
					end
					steer (node_angle, cruise_speed)
				end
			end
		end

	begin_following (a_scan: LASER_SIGNALER)
			-- Switch to boundary following, on the side of the last node.
		do
			mode := Boundary_following
			boundary_count := boundary_count + 1
			if steered_side /= 0 then
					-- Go on round the obstacle the way the robot was going (past its last node).
				follow_side := - steered_side
			elseif normalized_angle (a_scan.angle (a_scan.nearest_in (goal_angle - Pi / 2.0, goal_angle + Pi / 2.0).max (1))
				- goal_angle) >= 0.0
			then
				follow_side := 1
			else
				follow_side := -1
			end
			steered_side := 0
			has_hit := False
			has_followed_point := False
			rise_count := 0
			follow_travel := 0.0
			has_left_hit := False
			d_followed := Infinity
			follow_boundary (a_scan)
		ensure
			following: mode = Boundary_following or mode = Goal_unreachable
		end

	steer (a_angle, a_speed: REAL_64)
			-- Aim at direction `a_angle' (from the heading) at `a_speed'.
		do
			target_heading := normalized_angle (theta + a_angle)
			target_speed := a_speed.min (distance_to_goal + 0.05)
		end

feature {NONE} -- Boundary following

	follow_boundary (a_scan: LASER_SIGNALER)
			-- Follow the obstacle on `follow_side'; leave it, or find the goal unreachable.
		local
			nb: INTEGER
			away: REAL_64
		do
			nb := followed_beam (a_scan)
			if nb > 0 then
				note_followed (a_scan, a_scan.segment (nb))
			end
			d_reach := reachable_distance
			if not has_hit and nb > 0 and then a_scan.range (nb) < follow_distance + 0.1 then
					-- Now beside the boundary: loops are measured from here.
				hit_x := x
				hit_y := y
				has_hit := True
				follow_travel := 0.0
			end
			away := distance (x, y, hit_x, hit_y)
			if has_hit and away > Loop_away then
				has_left_hit := True
			end
			if d_reach < d_followed - Leave_slack then
				mode := Motion_to_goal
				leave_count := leave_count + 1
				is_in_transit := True
				transit_x := reach_x
				transit_y := reach_y
				transit_limit := d_reach + Transit_reached
				transit_best := Infinity
				progress_plan := plan_count
				move_to_goal (a_scan)
			elseif has_left_hit and away < Loop_back and follow_travel > 4.0 * Loop_away then
				mode := Goal_unreachable
			else
				keep_beside (a_scan, nb)
			end
		end

	followed_beam (a_scan: LASER_SIGNALER): INTEGER
			-- The beam that sees the followed boundary (0 when none): on the followed side (or ahead),
			-- the nearest point close to the one followed at the last plan (so the robot keeps to
			-- one boundary where another one is near), else the nearest point there.
		local
			i, nearest, continued: INTEGER
			a, r, px, py, best, best_continued: REAL_64
		do
			best := Infinity
			best_continued := Infinity
			from i := 1 until i > a_scan.beam_count loop
				r := a_scan.range (i)
				a := a_scan.angle (i)
				if r < best_continued and then ((follow_side > 0 and a >= - Pi / 3.0) or (follow_side < 0 and a <= Pi / 3.0)) then
					if r < best then
						best := r
						nearest := i
					end
					if has_followed_point then
						px := x + r * cosine (theta + a)
						py := y + r * sine (theta + a)
						if distance (px, py, followed_x, followed_y) < Continuity then
							best_continued := r
							continued := i
						end
					end
				end
				i := i + 1
			end
			if continued > 0 and best > radius + 0.1 then
				Result := continued
			else
				Result := nearest
			end
			has_followed_point := Result > 0
			if has_followed_point then
				followed_x := x + a_scan.range (Result) * cosine (theta + a_scan.angle (Result))
				followed_y := y + a_scan.range (Result) * sine (theta + a_scan.angle (Result))
			end
		end

	note_followed (a_scan: LASER_SIGNALER; a_segment: INTEGER)
			-- Lower `d_followed' with the points of obstacle segment `a_segment'.
		local
			i: INTEGER
			r, a: REAL_64
		do
			from i := 1 until i > a_scan.beam_count loop
				if a_scan.segment (i) = a_segment then
					r := a_scan.range (i)
					a := theta + a_scan.angle_min + (i - 1) * a_scan.angle_increment
					d_followed := d_followed.min (distance (x + r * cosine (a), y + r * sine (a), goal_x, goal_y))
				end
				i := i + 1
			end
		end

	reachable_distance: REAL_64
			-- Smallest distance to the goal of a point the robot can reach in a straight line now
			-- (the point: `reach_x', `reach_y').
		do
			Result := distance_to_goal - goal_clear
			reach_x := x + goal_clear * cosine (theta + goal_angle)
			reach_y := y + goal_clear * sine (theta + goal_angle)
			if has_node and then nearest_node_distance < Result then
				Result := nearest_node_distance
				reach_x := nearest_node_x
				reach_y := nearest_node_y
			end
		end

	keep_beside (a_scan: LASER_SIGNALER; a_beam: INTEGER)
			-- Aim along the obstacle seen by `a_beam', `follow_distance' from it (towards its side when none).
		local
			correction, r: REAL_64
		do
			if a_beam = 0 then
				target_heading := normalized_angle (theta + follow_side * 0.6)
				target_speed := 0.5 * follow_speed
			else
				r := a_scan.range (a_beam)
				if r < radius + 0.05 then
						-- Too close: get away first, slightly along the way.
					target_heading := normalized_angle (theta + a_scan.angle (a_beam) + Pi - follow_side * 0.5)
					target_speed := 0.5 * follow_speed
				else
					correction := (1.5 * (r - follow_distance)).max (-0.8).min (0.8)
					target_heading := normalized_angle (theta + a_scan.angle (a_beam) - follow_side * Pi / 2.0 + follow_side * correction)
					target_speed := follow_speed
				end
			end
		end

feature {NONE} -- Local tangent graph

	find_nodes (a_scan: LASER_SIGNALER)
			-- Set `goal_free', `goal_clear' and the best endpoint node.
		local
			k, i, side: INTEGER
			r, offset, a, nx, ny, h, reach, look, half_width: REAL_64
		do
			half_width := radius + margin
			look := distance_to_goal.min (a_scan.range_max)
			goal_clear := a_scan.clear_length (goal_angle, half_width, look)
			goal_free := goal_clear >= look - 0.01
			has_node := False
			node_heuristic := Infinity
			nearest_node_distance := Infinity
			from k := 1 until k > a_scan.endpoint_count loop
				i := a_scan.endpoint_beam (k)
				side := a_scan.endpoint_side (k)
				r := a_scan.range (i)
				offset := arc_sine ((half_width / r).min (1.0))
				a := a_scan.angle (i) + side * offset
				reach := a_scan.clear_length (a, radius + 0.03, r)
				if reach >= r - 0.05 then
					nx := x + r * cosine (theta + a)
					ny := y + r * sine (theta + a)
					h := r + distance (nx, ny, goal_x, goal_y)
					if distance (nx, ny, goal_x, goal_y) > distance_to_goal - Progress_step then
							-- Not closer to the goal than the robot: no way forward in motion to goal.
						h := Infinity
					end
					if distance (nx, ny, goal_x, goal_y) < nearest_node_distance then
						nearest_node_distance := distance (nx, ny, goal_x, goal_y)
						nearest_node_x := nx
						nearest_node_y := ny
					end
					if h < node_heuristic then
						node_heuristic := h
						node_angle := normalized_angle (a)
						node_side := side
						has_node := True
					end
				end
				k := k + 1
			end
		end

feature {NONE} -- Implementation

	x, y, theta: REAL_64
			-- Pose at the last update.

	has_pose: BOOLEAN
			-- Has `update' been called?

	goal_angle: REAL_64
			-- Direction of the goal from the heading, at the last plan.

	has_plan: BOOLEAN
			-- Has a scan been planned with?

	scan_x, scan_y, scan_theta: REAL_64
			-- Pose at the last plan (taken as the scan's).

	target_heading: REAL_64
			-- Heading to turn to (world frame).

	target_speed: REAL_64
			-- Forward speed wanted when facing `target_heading'.

	goal_free: BOOLEAN
			-- Is the way to the goal clear (as far as the laser sees)?

	goal_clear: REAL_64
			-- How far the robot can go towards the goal in a straight line.

	has_node: BOOLEAN
			-- Was an endpoint node found?

	node_heuristic, node_angle: REAL_64
			-- Best endpoint: heuristic distance and direction.

	node_side: INTEGER
			-- Open side of the best endpoint.

	steered_side: INTEGER
			-- Open side of the endpoint the robot heads for (0: heading for the goal or a transit point).

	nearest_node_distance: REAL_64
			-- Smallest distance from an endpoint node to the goal.

	nearest_node_x, nearest_node_y: REAL_64
			-- That node.

	reach_x, reach_y: REAL_64
			-- The point of `d_reach'.

	is_in_transit: BOOLEAN
			-- Heading for the point that allowed leaving the boundary?

	transit_x, transit_y: REAL_64
			-- That point.

	transit_limit: REAL_64
			-- As close to the goal as the transit point (nearly): closer than this ends the transit.

	transit_best: REAL_64
			-- Smallest distance to the transit point so far.

	rise_count: INTEGER
			-- Consecutive plans whose heuristic distance exceeded the best by `Heuristic_slack'.

	plan_count, progress_plan: INTEGER
			-- Plans in motion to goal; the last one that made progress.

	progress_reference: REAL_64
			-- Heuristic distance at the last progress.

	has_followed_point: BOOLEAN
			-- Is `followed_x', `followed_y' known?

	followed_x, followed_y: REAL_64
			-- The boundary point followed at the last plan.

	follow_travel: REAL_64
			-- Distance travelled since boundary following began.

	has_left_hit: BOOLEAN
			-- Has the robot gone `Loop_away' from the hit point?

	Infinity: REAL_64
			-- Larger than any distance.
		once
			Result := {REAL_64}.positive_infinity
		end

	distance (x1, y1, x2, y2: REAL_64): REAL_64
			-- Euclidean distance.
		do
			Result := sqrt ((x2 - x1) ^ 2 + (y2 - y1) ^ 2)
		end

end
