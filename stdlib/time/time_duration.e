note
	description: "[
		Lengths of time in hours, minutes and seconds (with a fraction), possibly negative.
		The parts are kept as given (90 minutes stay 90 minutes) until `to_canonical'
		brings each of them into its usual range, all with the sign of the whole.
	]"

class
	TIME_DURATION

inherit
	DURATION
		redefine
			is_equal
		end

	TIME_CONSTANTS
		undefine
			is_equal
		end

	TIME_UTILITY
		undefine
			is_equal
		end

create
	make,
	make_fine,
	make_by_seconds,
	make_by_fine_seconds

feature {NONE} -- Initialization

	make (h, m, s: INTEGER_32)
			-- A duration of `h' hours, `m' minutes and `s' seconds.
		do
			hour := h
			minute := m
			fine_second := s
		ensure
			hour_set: hour = h
			minute_set: minute = m
			second_set: second = s
		end

	make_fine (h, m: INTEGER_32; s: REAL_64)
			-- A duration of `h' hours, `m' minutes and `s' seconds.
		do
			hour := h
			minute := m
			fine_second := s
		ensure
			hour_set: hour = h
			minute_set: minute = m
			fine_second_set: fine_second = s
		end

	make_by_seconds (s: INTEGER_32)
			-- A duration of `s' seconds, spread into hours and minutes.
		do
			make_by_fine_seconds (s)
		ensure
			seconds_count_set: seconds_count = s
		end

	make_by_fine_seconds (s: REAL_64)
			-- A duration of `s' seconds, spread into hours and minutes
			-- (minutes and seconds not negative).
		local
			l_whole: INTEGER_32
		do
			l_whole := s.floor
			hour := div (l_whole, Seconds_in_hour)
			minute := mod (l_whole, Seconds_in_hour) // Seconds_in_minute
			fine_second := s - (hour.to_double * Seconds_in_hour + minute.to_double * Seconds_in_minute)
		ensure
			minute_large_enough: minute >= 0
			minute_small_enough: minute < Minutes_in_hour
		end

feature -- Access

	hour: INTEGER_32
			-- Hours of the duration.

	minute: INTEGER_32
			-- Minutes of the duration.

	fine_second: REAL_64
			-- Seconds of the duration, with their fraction.

	second: INTEGER_32
			-- Whole seconds of the duration (`fine_second' rounded toward zero).
		do
			Result := fine_second.truncated_to_integer
		end

	fractional_second: REAL_64
			-- Fraction of a second of the duration (same sign as `fine_second').
		do
			Result := fine_second - second
		end

	fine_seconds_count: REAL_64
			-- The whole duration in seconds.
		do
			Result := hour.to_double * Seconds_in_hour + minute.to_double * Seconds_in_minute + fine_second
		end

	seconds_count: INTEGER_64
			-- The whole duration in seconds, fraction dropped (rounded toward zero).
		do
			Result := fine_seconds_count.truncated_to_integer_64
		end

	zero: TIME_DURATION
			-- The empty duration.
		do
			create Result.make (0, 0, 0)
		end

feature -- Comparison

	is_less alias "<" (other: like Current): BOOLEAN
			-- Is the duration shorter than `other'?
		do
			Result := fine_seconds_count < other.fine_seconds_count
		end

	is_equal (other: like Current): BOOLEAN
			-- Is the duration as long as `other'?
		do
			Result := fine_seconds_count = other.fine_seconds_count
		end

feature -- Status report

	canonical: BOOLEAN
			-- Are minutes and seconds within a minute/hour of zero and of the sign of the whole?
		do
			if fine_seconds_count >= 0 then
				Result := (minute >= 0 and minute < Minutes_in_hour) and (fine_second >= 0 and fine_second < Seconds_in_minute)
			else
				Result := (minute <= 0 and minute > -Minutes_in_hour) and (fine_second <= 0 and fine_second > -Seconds_in_minute)
			end
		end

	is_positive: BOOLEAN
			-- Is some part of the duration above zero?
		do
			Result := hour > 0 or minute > 0 or fine_second > 0
		end

	is_negative: BOOLEAN
			-- Is the duration below zero?
		do
			Result := fine_seconds_count < 0
		end

	is_zero: BOOLEAN
			-- Is the duration empty?
		do
			Result := fine_seconds_count = 0
		end

feature -- Element change

	set_hour (h: INTEGER_32)
			-- Make `h' the hours.
		do
			hour := h
		ensure
			hour_set: hour = h
		end

	set_minute (m: INTEGER_32)
			-- Make `m' the minutes.
		do
			minute := m
		ensure
			minute_set: minute = m
		end

	set_second (s: INTEGER_32)
			-- Make `s' the seconds (no fraction).
		do
			fine_second := s
		ensure
			second_set: second = s
		end

	set_fine_second (s: REAL_64)
			-- Make `s' the seconds.
		do
			fine_second := s
		ensure
			fine_second_set: fine_second = s
		end

	set_fractionals (f: REAL_64)
			-- Make `f' the fraction of the second (same sign as `second').
		do
			fine_second := second + f
		end

	hour_add (h: INTEGER_32)
			-- Add `h' hours.
		do
			hour := hour + h
		ensure
			hour_set: hour = old hour + h
		end

	minute_add (m: INTEGER_32)
			-- Add `m' minutes.
		do
			minute := minute + m
		ensure
			minute_set: minute = old minute + m
		end

	second_add (s: INTEGER_32)
			-- Add `s' seconds.
		do
			fine_second := fine_second + s
		end

	fine_second_add (s: REAL_64)
			-- Add `s' seconds.
		do
			fine_second := fine_second + s
		end

feature -- Basic operations

	plus alias "+" (other: like Current): like Current
			-- Sum of the duration and `other', part by part.
		do
			Result := twin
			Result.set_hour (hour + other.hour)
			Result.set_minute (minute + other.minute)
			Result.set_fine_second (fine_second + other.fine_second)
		end

	minus alias "-" (other: like Current): like Current
			-- The duration less `other', part by part.
		do
			Result := Current + (- other)
		end

	opposite alias "-": like Current
			-- The duration with every part negated.
		do
			Result := twin
			Result.set_hour (- hour)
			Result.set_minute (- minute)
			Result.set_fine_second (- fine_second)
		end

feature -- Conversion

	to_canonical: like Current
			-- The same length with minutes and seconds in their ranges, all parts of one sign.
		do
			Result := twin
			if fine_seconds_count >= 0 then
				Result.set_from_seconds (fine_seconds_count)
			else
				Result.set_from_seconds (- fine_seconds_count)
				Result := - Result
			end
		ensure
			result_canonical: Result.canonical
		end

	to_days: INTEGER_32
			-- Number of whole days in the duration (rounded toward minus infinity).
		do
			Result := div (fine_seconds_count.floor, Seconds_in_day)
		end

	time_modulo_day: like Current
			-- What is left of the duration once whole days are taken away (from 0 to less than a day).
		local
			l_seconds: REAL_64
		do
			l_seconds := fine_seconds_count - to_days.to_double * Seconds_in_day
			Result := twin
			Result.set_from_seconds (l_seconds)
		ensure
			less_than_a_day: Result.seconds_count < Seconds_in_day
			not_negative: not Result.is_negative
		end

feature {TIME_DURATION} -- Implementation

	set_from_seconds (s: REAL_64)
			-- Make the duration `s' seconds, spread into hours and minutes.
		do
			make_by_fine_seconds (s)
		end

invariant
	fractional_second_large_enough: fractional_second > -1
	fractional_second_small_enough: fractional_second < 1

end
