note
	description: "[
		Tests of robot programs (`scoopc test'): each test of a descendant runs in a simulated world
		of its own, on simulated time, and can then check what happened to the robot: where it is
		and where it went, collisions, holes, whether it stopped after a stop request, how far it
		drove, how much battery it has left.
		The world is the `world' note of the test routine, else of the test class (a world file,
		relative to the class's file), else world.yaml beside the class, else the built-in arena.
		The robot checked is the program's (ROBOT_ENVIRONMENT's `namespace': the world's first).
		A test starts the program's robot, behaviours and controllers, lets simulated time pass
		with `run_for', and asserts. When the test routine is over, its world stops (the
		controllers it started with it). The same test in the same world gives the same run.
	]"

deferred class
	ROBOT_TEST_SET

inherit
	EQA_TEST_SET

feature -- Simulation

	run_for (a_seconds: REAL_64)
			-- Let `a_seconds' of simulated time pass: the test waits, the world and the program run.
		require
			not_negative: a_seconds >= 0.0
		do
			(create {EXECUTION_ENVIRONMENT}).sleep ((a_seconds * 1.0e9).truncated_to_integer_64)
		end

	simulated_time: REAL_64
			-- Seconds of simulated time since the test's world started.
		external
			"Python"
		end

	mark_stop_request
			-- Note that a stop is requested now (for `assert_stopped_within').
		external
			"Python"
		end

	stop_requested_at: REAL_64
			-- When `mark_stop_request' was last called (simulated seconds), or -1.
		external
			"Python"
		end

feature -- The robot

	robot_x, robot_y: REAL_64
			-- Where the robot is (world coordinates, m).
		external
			"Python"
		end

	robot_heading: REAL_64
			-- Where it faces (rad, counterclockwise from the x axis).
		external
			"Python"
		end

	closest_approach (x, y: REAL_64): REAL_64
			-- The smallest distance between the robot and (`x', `y') during the run (m).
		external
			"Python"
		end

	distance_driven: REAL_64
			-- The length of the robot's path (m).
		external
			"Python"
		end

	battery_left: REAL_64
			-- The robot's battery charge, from 0 (empty) to 1 (full).
		external
			"Python"
		end

	collision_count: INTEGER
			-- Times the robot ran into a wall, an obstacle or another robot.
		external
			"Python"
		end

	has_fallen: BOOLEAN
			-- Did the robot drive into a hole?
		external
			"Python"
		end

	last_moved_at: REAL_64
			-- When the robot last moved or turned (simulated seconds), or 0 if it never did.
		external
			"Python"
		end

feature -- Assertions

	assert_at_position (a_tag: READABLE_STRING_GENERAL; x, y, a_tolerance: REAL_64)
			-- Check that the robot is now within `a_tolerance' of (`x', `y').
		require
			tolerance_not_negative: a_tolerance >= 0.0
		do
			assert (with_values (a_tag, "at most " + fixed (a_tolerance) + " m from (" + fixed (x) + ", " + fixed (y) + ")",
				"at (" + fixed (robot_x) + ", " + fixed (robot_y) + ")"),
				distance_to (x, y) <= a_tolerance)
		end

	assert_position_reached (a_tag: READABLE_STRING_GENERAL; x, y, a_tolerance: REAL_64)
			-- Check that the robot came within `a_tolerance' of (`x', `y') at some time of the run.
		require
			tolerance_not_negative: a_tolerance >= 0.0
		do
			assert (with_values (a_tag, "within " + fixed (a_tolerance) + " m of (" + fixed (x) + ", " + fixed (y) + ")",
				"no closer than " + fixed (closest_approach (x, y)) + " m"),
				closest_approach (x, y) <= a_tolerance)
		end

	assert_no_collision (a_tag: READABLE_STRING_GENERAL)
			-- Check that the robot never ran into anything.
		do
			assert (with_values (a_tag, "no collision", collision_count.out + " collisions"), collision_count = 0)
		end

	assert_never_in_hole (a_tag: READABLE_STRING_GENERAL)
			-- Check that the robot never drove into a hole.
		do
			assert (with_values (a_tag, "never in a hole", "fell into a hole"), not has_fallen)
		end

	assert_stopped_within (a_tag: READABLE_STRING_GENERAL; a_seconds: REAL_64)
			-- Check that the robot has not moved since `a_seconds' after the last stop request.
		require
			stop_requested: stop_requested_at >= 0.0
			enough_time_simulated: simulated_time >= stop_requested_at + a_seconds
		do
			assert (with_values (a_tag, "still from " + fixed (stop_requested_at + a_seconds) + " s on",
				"last moved at " + fixed (last_moved_at) + " s"),
				last_moved_at <= stop_requested_at + a_seconds)
		end

	assert_distance_driven (a_tag: READABLE_STRING_GENERAL; a_min, a_max: REAL_64)
			-- Check that the robot's path is between `a_min' and `a_max' metres long.
		require
			range: a_min <= a_max
		do
			assert (with_values (a_tag, "between " + fixed (a_min) + " and " + fixed (a_max) + " m",
				fixed (distance_driven) + " m"),
				a_min <= distance_driven and distance_driven <= a_max)
		end

	assert_battery_left (a_tag: READABLE_STRING_GENERAL; a_min: REAL_64)
			-- Check that the robot has at least `a_min' of its battery left (0 to 1).
		do
			assert (with_values (a_tag, "at least " + fixed (a_min), fixed (battery_left)), battery_left >= a_min)
		end

feature {NONE} -- Implementation

	distance_to (x, y: REAL_64): REAL_64
			-- The robot's distance to (`x', `y') now.
		do
			Result := (create {ANGLE_MATH}).sqrt ((robot_x - x) * (robot_x - x) + (robot_y - y) * (robot_y - y))
		end

	fixed (v: REAL_64): STRING
			-- `v' with three decimals ("-0.125").
		local
			n: INTEGER_64
			fraction: STRING
		do
			n := (v.abs * 1000.0).rounded_real_64.truncated_to_integer_64
			fraction := (n \\ 1000).out
			from until fraction.count = 3 loop
				fraction.prepend_character ('0')
			end
			Result := (n // 1000).out + "." + fraction
			if v < 0.0 and n > 0 then
				Result.prepend_character ('-')
			end
		end

	with_values (a_tag: READABLE_STRING_GENERAL; expected, actual: STRING): STRING_32
			-- The message of a failed check.
		do
			Result := assert_strings_equal_message (a_tag, expected, actual)
			Result.append_string_general ("%N   at time: ")
			Result.append_string_general (fixed (simulated_time))
			Result.append_string_general (" s")
		end

end
