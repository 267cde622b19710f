note
	description: "[
		The grading tests of exercise 1 (README.md): TEMPERATURE_SIGNALER on a processor of its
		own, fed by the test or by a FEEDER on another processor.
	]"

class
	TEMPERATURE_SIGNALER_TESTS

inherit
	EQA_TEST_SET

feature -- Tests

	test_no_reading_at_first
			-- A new signaler has no reading and is not overheated.
		local
			s: separate TEMPERATURE_SIGNALER
		do
			create s.make (40.0)
			check_fresh (s)
		end

	test_latest_maximum_average
			-- Three readings: the latest, the highest and the mean.
		local
			s: separate TEMPERATURE_SIGNALER
		do
			create s.make (40.0)
			feed (s, 20.0)
			feed (s, 25.0)
			feed (s, 22.0)
			check_statistics (s)
		end

	test_overheating
			-- Overheated while the latest reading is above the limit, and only then.
		local
			s: separate TEMPERATURE_SIGNALER
		do
			create s.make (40.0)
			feed (s, 39.9)
			assert ("39.9 is not above 40", not is_overheated (s))
			feed (s, 40.5)
			assert ("40.5 is above 40", is_overheated (s))
			feed (s, 30.0)
			assert ("cooled down to 30", not is_overheated (s))
		end

	test_readings_from_another_processor
			-- A feeder on its own processor sends five readings; the test waits for them.
		local
			s: separate TEMPERATURE_SIGNALER
			f: separate FEEDER
		do
			create s.make (35.0)
			create f
			start_feeding (f, s)
			await_five (s)
		end

feature {NONE} -- Implementation

	check_fresh (s: separate TEMPERATURE_SIGNALER)
		do
			assert ("no reading", not s.has_reading)
			assert_integers_equal ("no reading counted", 0, s.reading_count)
			assert ("not overheated", not s.is_overheated)
			assert_reals_equal ("the limit", 40.0, s.limit, 0.0)
		end

	check_statistics (s: separate TEMPERATURE_SIGNALER)
		do
			assert ("a reading", s.has_reading)
			assert_integers_equal ("three readings", 3, s.reading_count)
			assert_reals_equal ("the latest", 22.0, s.celsius, 1.0e-9)
			assert_reals_equal ("the highest", 25.0, s.maximum, 1.0e-9)
			assert_reals_equal ("the mean", 67.0 / 3.0, s.average, 1.0e-9)
		end

	feed (s: separate TEMPERATURE_SIGNALER; a_celsius: REAL_64)
		do
			s.update (a_celsius)
		end

	is_overheated (s: separate TEMPERATURE_SIGNALER): BOOLEAN
		do
			Result := s.is_overheated
		end

	start_feeding (f: separate FEEDER; s: separate TEMPERATURE_SIGNALER)
		do
			f.feed (s)
		end

	await_five (s: separate TEMPERATURE_SIGNALER)
			-- Wait until five readings have come, then check them.
		require
			five_readings: s.reading_count >= 5
		do
			assert_reals_equal ("the highest of five", 36.0, s.maximum, 1.0e-9)
			assert_reals_equal ("the latest of five", 34.0, s.celsius, 1.0e-9)
			assert ("34 is not above 35", not s.is_overheated)
		end

end
