note
	description: "[
		Moments: a DATE and a TIME of day. Ordered; arithmetic carries seconds into
		minutes, hours and days. `out' writes "mm/dd/yyyy h:mm:ss.fff AM" (the hour on the
		12-hour clock, without a leading zero; milliseconds; AM or PM).
	]"
	implementation: "Plain Eiffel; `make_now' reads the clock through C_DATE."

class
	DATE_TIME

inherit
	COMPARABLE
		redefine
			is_equal,
			copy,
			out
		end

	DATE_CONSTANTS
		undefine
			is_equal,
			copy,
			out
		end

	TIME_CONSTANTS
		undefine
			is_equal,
			copy,
			out
		end

create
	make,
	make_fine,
	make_by_date_time,
	make_by_date,
	make_now,
	make_now_utc,
	make_from_epoch

feature {NONE} -- Initialization

	make (y, mo, d, h, mi, s: INTEGER_32)
			-- Day `d' of month `mo' of year `y', at `h':`mi':`s'.
		require
			correct_date_time: is_correct_date_time (y, mo, d, h, mi, s, False)
		do
			create date.make (y, mo, d)
			create time.make (h, mi, s)
		ensure
			year_set: year = y
			month_set: month = mo
			day_set: day = d
			hour_set: hour = h
			minute_set: minute = mi
			second_set: second = s
		end

	make_fine (y, mo, d, h, mi: INTEGER_32; s: REAL_64)
			-- Day `d' of month `mo' of year `y', at `h':`mi':`s' (`s' with a fraction).
		require
			correct_date_time: is_correct_date_time (y, mo, d, h, mi, s, False)
		do
			create date.make (y, mo, d)
			create time.make_fine (h, mi, s)
		ensure
			year_set: year = y
			month_set: month = mo
			day_set: day = d
			hour_set: hour = h
			minute_set: minute = mi
		end

	make_by_date_time (d: DATE; t: TIME)
			-- The moment of date `d' at time `t' (both kept, not copied).
		do
			date := d
			time := t
		ensure
			date_set: date = d
			time_set: time = t
		end

	make_by_date (d: DATE)
			-- Midnight of date `d' (kept, not copied).
		do
			date := d
			create time.make (0, 0, 0)
		ensure
			date_set: date = d
			time_set: time.seconds = 0
		end

	make_now
			-- Now, in local time (to the millisecond).
		local
			l_now: C_DATE
		do
			create l_now
			create date.make (l_now.year_now, l_now.month_now, l_now.day_now)
			create time.make_fine (l_now.hour_now, l_now.minute_now, l_now.second_now + l_now.millisecond_now / 1000)
		end

	make_now_utc
			-- Now, in UTC (to the millisecond).
		local
			l_now: C_DATE
		do
			create l_now.make_utc
			create date.make (l_now.year_now, l_now.month_now, l_now.day_now)
			create time.make_fine (l_now.hour_now, l_now.minute_now, l_now.second_now + l_now.millisecond_now / 1000)
		end

	make_from_epoch (s: INTEGER_32)
			-- The moment `s' seconds after 1970-01-01 00:00:00 (before it if `s' is negative).
		do
			create date.make (1970, 1, 1)
			date.day_add (div (s, Seconds_in_day))
			create time.make_by_seconds (mod (s, Seconds_in_day))
		end

feature -- Access

	date: DATE
			-- The day.

	time: TIME
			-- The time of day.

	year: INTEGER_32
			-- Year.
		do
			Result := date.year
		end

	month: INTEGER_32
			-- Month (1 to 12).
		do
			Result := date.month
		end

	day: INTEGER_32
			-- Day of the month.
		do
			Result := date.day
		end

	hour: INTEGER_32
			-- Hour (0 to 23).
		do
			Result := time.hour
		end

	minute: INTEGER_32
			-- Minute (0 to 59).
		do
			Result := time.minute
		end

	second: INTEGER_32
			-- Whole second (0 to 59).
		do
			Result := time.second
		end

	fine_second: REAL_64
			-- Second with its fraction.
		do
			Result := time.fine_second
		end

	fractional_second: REAL_64
			-- Fraction of the second.
		do
			Result := time.fractional_second
		end

	origin: DATE_TIME
			-- The moment days are counted from: 1600-01-01 at midnight.
		do
			create Result.make (1600, 1, 1, 0, 0, 0)
		end

	days: INTEGER_32
			-- Number of days from `origin' to `date'.
		do
			Result := date.days
		end

	seconds: INTEGER_32
			-- Number of whole seconds since midnight.
		do
			Result := time.seconds
		end

	date_duration: DATE_DURATION
			-- Days from `origin' to `date'.
		do
			Result := date.duration
		end

	time_duration: TIME_DURATION
			-- Time since midnight.
		do
			Result := time.duration
		end

	default_format_string: STRING_8 = "[0]mm/[0]dd/yyyy hh12:[0]mi:[0]ss.ff3 AM"
			-- How `out' writes a moment.

feature -- Measurement

	duration: DATE_TIME_DURATION
			-- Time since `origin' (definite: days and time of day).
		do
			create Result.make_by_date_time (date_duration, time_duration)
		ensure
			definite_result: Result.definite
		end

feature -- Status report

	is_correct_date_time (y, mo, d, h, mi: INTEGER_32; s: REAL_64; twelve_hour_scale: BOOLEAN): BOOLEAN
			-- Is `h':`mi':`s' of day `d' of month `mo' of year `y' a moment this class can hold?
		do
			Result := is_correct_date (y, mo, d) and is_correct_time (h, mi, s, twelve_hour_scale)
		end

feature -- Comparison

	is_less alias "<" (other: like Current): BOOLEAN
			-- Is the moment before `other'?
		do
			Result := date < other.date or else (date.is_equal (other.date) and then time < other.time)
		end

	is_equal (other: like Current): BOOLEAN
			-- Is `other' the same moment?
		do
			Result := date.is_equal (other.date) and time.is_equal (other.time)
		end

feature -- Element change

	set_date (d: DATE)
			-- Make `d' the day (kept, not copied).
		do
			date := d
		ensure
			date_set: date = d
		end

	set_time (t: TIME)
			-- Make `t' the time of day (kept, not copied).
		do
			time := t
		ensure
			time_set: time = t
		end

feature -- Duplication

	copy (other: like Current)
			-- Take the date and time of `other', in objects of its own.
		do
			if other /= Current then
				standard_copy (other)
				date := other.date.twin
				time := other.time.twin
			end
		end

feature -- Basic operations

	plus alias "+" (d: DATE_TIME_DURATION): like Current
			-- The moment `d' later.
		do
			Result := twin
			Result.add (d)
		end

	add (d: DATE_TIME_DURATION)
			-- Move `d' later: years and months first (the day cut to the month's length
			-- if needed), then days, then the time, carried into days.
		local
			l_time: TIME_DURATION
		do
			if not d.definite then
				date.year_month_add (d.year, d.month)
			end
			day_add (d.day)
			l_time := d.time + time_duration
			day_add (l_time.to_days)
			time := time.origin + l_time.time_modulo_day
		end

	relative_duration (other: like Current): DATE_TIME_DURATION
			-- Duration from `other' to the moment, in canonical form, starting from `other'.
		do
			create Result.make_fine (0, 0, days - other.days, hour - other.hour, minute - other.minute,
				fine_second - other.fine_second)
			Result := Result.to_canonical (other)
			Result.set_origin_date_time (other.twin)
		ensure
			origin_set: attached Result.origin_date_time as o and then o.is_equal (other)
		end

	definite_duration (other: like Current): DATE_TIME_DURATION
			-- Duration from `other' to the moment, in days and time (no years or months).
		do
			Result := relative_duration (other)
			Result.date.to_definite (other.date)
		ensure
			definite_result: Result.definite
		end

	day_add (d: INTEGER_32)
			-- Move `d' days later (earlier if `d' is negative).
		do
			date.day_add (d)
		ensure
			days_set: days = old days + d
		end

	hour_add (h: INTEGER_32)
			-- Move `h' hours later (earlier if negative), changing the day if needed.
		local
			l_hours: INTEGER_32
		do
			l_hours := hour + h
			time.set_hour (mod (l_hours, Hours_in_day))
			day_add (div (l_hours, Hours_in_day))
		end

	minute_add (m: INTEGER_32)
			-- Move `m' minutes later (earlier if negative), changing the hour and day if needed.
		local
			l_minutes: INTEGER_32
		do
			l_minutes := minute + m
			time.set_minute (mod (l_minutes, Minutes_in_hour))
			hour_add (div (l_minutes, Minutes_in_hour))
		end

	second_add (s: INTEGER_32)
			-- Move `s' seconds later (earlier if negative), changing the minute, hour and day if needed.
		local
			l_seconds: INTEGER_32
			l_fraction: REAL_64
		do
			l_seconds := second + s
			l_fraction := fractional_second
			time.set_fine_second (mod (l_seconds, Seconds_in_minute) + l_fraction)
			minute_add (div (l_seconds, Seconds_in_minute))
		end

	fine_second_add (s: REAL_64)
			-- Move `s' seconds later (earlier if negative), changing the minute, hour and day if needed.
		local
			l_seconds: REAL_64
			l_minutes: INTEGER_32
		do
			l_seconds := fine_second + s
			l_minutes := div (l_seconds.floor, Seconds_in_minute)
			time.set_fine_second (l_seconds - l_minutes.to_double * Seconds_in_minute)
			minute_add (l_minutes)
		end

feature -- Output

	out: STRING_8
			-- The moment as `default_format_string' says: `date.out', a space, `time.out'
			-- (e.g. "01/05/2024 3:07:09.000 PM").
		do
			Result := date.out
			Result.append_character (' ')
			Result.append (time.out)
		end

end
