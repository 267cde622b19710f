note
	description: "[
		Times of day, to a fraction of a second: hour, minute, second. Arithmetic
		(`second_add', ...) wraps around midnight. `out' writes EiffelTime's English
		default format "hh12:[0]mi:[0]ss.ff3 AM" (e.g. "3:07:09.250 PM").
	]"
	implementation: "Plain Eiffel; `make_now' asks the host for the time of day (`external %"Python%"')."

class
	TIME

inherit
	COMPARABLE
		redefine
			out
		end

	TIME_CONSTANTS
		undefine
			out,
			is_equal
		end

create
	make,
	make_fine,
	make_now,
	make_now_utc,
	make_by_seconds,
	make_by_fine_seconds

feature {NONE} -- Initialization

	make (h, m, s: INTEGER_32)
			-- Time `h':`m':`s'.
		require
			correct_hour: h >= 0 and h < Hours_in_day
			correct_minute: m >= 0 and m < Minutes_in_hour
			correct_second: s >= 0 and s < Seconds_in_minute
		do
			hour := h
			minute := m
			second := s
			fractional_second := 0.0
		ensure
			hour_set: hour = h
			minute_set: minute = m
			second_set: second = s
		end

	make_fine (h, m: INTEGER_32; s: REAL_64)
			-- Time `h':`m':`s', `s' having a fractional part.
		require
			correct_hour: h >= 0 and h < Hours_in_day
			correct_minute: m >= 0 and m < Minutes_in_hour
			correct_second: s >= 0.0 and s < Seconds_in_minute
		do
			hour := h
			minute := m
			second := s.floor
			fractional_second := s - second
		end

	make_now
			-- The local time of day now.
		do
			set_from_fine_seconds (fine_seconds_now (False))
		end

	make_now_utc
			-- The UTC time of day now.
		do
			set_from_fine_seconds (fine_seconds_now (True))
		end

	make_by_seconds (sec: INTEGER_32)
			-- The time `sec' seconds after midnight.
		require
			s_large_enough: sec >= 0
			s_small_enough: sec < Seconds_in_day
		do
			set_from_fine_seconds (sec)
		ensure
			seconds_set: seconds = sec
		end

	make_by_fine_seconds (sec: REAL_64)
			-- The time `sec' seconds after midnight.
		require
			s_large_enough: sec >= 0.0
			s_small_enough: sec < Seconds_in_day
		do
			set_from_fine_seconds (sec)
		end

feature -- Access

	hour: INTEGER_32
			-- Hour (0 to 23).

	minute: INTEGER_32
			-- Minute (0 to 59).

	second: INTEGER_32
			-- Whole second (0 to 59).

	fractional_second: REAL_64
			-- Fraction of the second (0 to less than 1).

	fine_second: REAL_64
			-- Second with its fraction.
		do
			Result := fractional_second + second
		end

	milli_second: INTEGER_32
			-- Millisecond within the second.
		do
			Result := (fractional_second * 1000).floor
		end

	seconds: INTEGER_32
			-- Whole seconds since midnight.
		do
			Result := (hour * Minutes_in_hour + minute) * Seconds_in_minute + second
		end

	fine_seconds: REAL_64
			-- Seconds since midnight, with the fraction.
		do
			Result := fractional_second + seconds
		end

	origin: TIME
			-- Midnight, 00:00:00.
		do
			create Result.make (0, 0, 0)
		end

feature -- Measurement

	duration: TIME_DURATION
			-- Time elapsed since midnight.
		do
			create Result.make_fine (hour, minute, fine_second)
		ensure
			seconds_large_enough: Result.seconds_count >= 0
			seconds_small_enough: Result.seconds_count < Seconds_in_day
		end

feature -- Comparison

	is_less alias "<" (other: like Current): BOOLEAN
			-- Is the current time earlier in the day than `other'?
		do
			Result := fine_seconds < other.fine_seconds
		end

feature -- Element change

	set_hour (h: INTEGER_32)
			-- Make `h' the hour.
		require
			correct_hour: h >= 0 and h < Hours_in_day
		do
			hour := h
		end

	set_minute (m: INTEGER_32)
			-- Make `m' the minute.
		require
			correct_minute: m >= 0 and m < Minutes_in_hour
		do
			minute := m
		end

	set_second (s: INTEGER_32)
			-- Make `s' the second (no fraction).
		require
			correct_second: s >= 0 and s < Seconds_in_minute
		do
			second := s
			fractional_second := 0.0
		end

	set_fine_second (s: REAL_64)
			-- Make `s' the second, with its fraction.
		require
			correct_second: s >= 0.0 and s < Seconds_in_minute
		do
			second := s.floor
			fractional_second := s - second
		end

	hour_add (h: INTEGER_32)
			-- Move `h' hours forward (backward if negative), around midnight.
		do
			set_from_fine_seconds (fine_seconds + h.to_double * Seconds_in_hour)
		end

	minute_add (m: INTEGER_32)
			-- Move `m' minutes forward (backward if negative), around midnight.
		do
			set_from_fine_seconds (fine_seconds + m.to_double * Seconds_in_minute)
		end

	second_add (s: INTEGER_32)
			-- Move `s' seconds forward (backward if negative), around midnight.
		do
			set_from_fine_seconds (fine_seconds + s)
		end

	fine_second_add (s: REAL_64)
			-- Move `s' seconds forward (backward if negative), around midnight.
		do
			set_from_fine_seconds (fine_seconds + s)
		end

feature -- Basic operations

	plus alias "+" (t: TIME_DURATION): TIME
			-- The time `t' later (earlier if `t' is negative), around midnight.
		do
			Result := twin
			Result.fine_second_add (t.fine_seconds_count)
		end

	relative_duration (other: like Current): TIME_DURATION
			-- Time from `other' to the current time (negative if `other' is later), in canonical form.
		do
			create Result.make_by_fine_seconds (fine_seconds - other.fine_seconds)
			Result := Result.to_canonical
		end

feature -- Output

	time_default_format_string: STRING_8 = "hh12:[0]mi:[0]ss.ff3 AM"
			-- How `out' writes a time (EiffelTime's English default).

	out: STRING_8
			-- The time as `time_default_format_string' says: the hour on the 12-hour clock
			-- without a leading zero, minutes and seconds on two digits, milliseconds
			-- (rounded) on three, then AM or PM.
		local
			l_hour: INTEGER_32
		do
			create Result.make (15)
			l_hour := hour \\ 12
			if l_hour = 0 then
				l_hour := 12
			end
			Result.append_integer (l_hour)
			Result.append_character (':')
			append_two_digits (Result, minute)
			Result.append_character (':')
			append_two_digits (Result, second)
			Result.append_character ('.')
			append_milliseconds (Result, (fractional_second * 1000).rounded)
			if hour < 12 then
				Result.append (" AM")
			else
				Result.append (" PM")
			end
		end

feature {NONE} -- Implementation

	set_from_fine_seconds (a_seconds: REAL_64)
			-- Set the time to `a_seconds' after midnight, brought back into one day.
		local
			l_total: REAL_64
			l_whole: INTEGER_32
		do
			l_total := a_seconds - (a_seconds / Seconds_in_day).floor_real_64 * Seconds_in_day
			l_whole := l_total.floor
			if l_whole >= Seconds_in_day then
				l_whole := Seconds_in_day - 1
			end
			hour := l_whole // Seconds_in_hour
			minute := (l_whole \\ Seconds_in_hour) // Seconds_in_minute
			second := l_whole \\ Seconds_in_minute
			fractional_second := l_total - l_whole
		end

	append_two_digits (s: STRING_8; n: INTEGER_32)
			-- Append `n' to `s' on at least two digits.
		do
			if n < 10 then
				s.append_character ('0')
			end
			s.append_integer (n)
		end

	append_milliseconds (s: STRING_8; n: INTEGER_32)
			-- Append `n' to `s' on at least three digits.
		do
			if n < 100 then
				s.append_character ('0')
			end
			append_two_digits (s, n)
		end

	fine_seconds_now (a_utc: BOOLEAN): REAL_64
			-- Seconds since midnight now, in UTC if `a_utc', local time otherwise.
		external
			"Python"
		end

invariant
	hour_in_range: hour >= 0 and hour < Hours_in_day
	minute_in_range: minute >= 0 and minute < Minutes_in_hour
	second_in_range: second >= 0 and second < Seconds_in_minute
	fraction_in_range: fractional_second >= 0.0 and fractional_second < 1.0

end
