note
	description: "[
		Lengths of time made of a DATE_DURATION (years, months, days) and a TIME_DURATION
		(hours, minutes, seconds). Its length in seconds is known when it is `definite'
		(no years, no months) or once an `origin_date_time' is set, as `relative_duration' does.
	]"

class
	DATE_TIME_DURATION

inherit
	DURATION
		redefine
			is_equal,
			copy
		end

	TIME_CONSTANTS
		undefine
			is_equal,
			copy
		end

create
	make,
	make_definite,
	make_fine,
	make_by_date_time,
	make_by_date

feature {NONE} -- Initialization

	make (y, mo, d, h, mi, s: INTEGER_32)
			-- A duration of `y' years, `mo' months, `d' days, `h' hours, `mi' minutes and `s' seconds.
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

	make_definite (d, h, m, s: INTEGER_32)
			-- A duration of `d' days, `h' hours, `m' minutes and `s' seconds.
		do
			create date.make_by_days (d)
			create time.make (h, m, s)
		ensure
			definite_result: definite
			day_set: day = d
			hour_set: hour = h
			minute_set: minute = m
			second_set: second = s
		end

	make_fine (y, mo, d, h, mi: INTEGER_32; s: REAL_64)
			-- A duration of `y' years, `mo' months, `d' days, `h' hours, `mi' minutes and `s' seconds.
		do
			create date.make (y, mo, d)
			create time.make_fine (h, mi, s)
		ensure
			year_set: year = y
			month_set: month = mo
			day_set: day = d
			hour_set: hour = h
			minute_set: minute = mi
			fine_second_set: fine_second = s
		end

	make_by_date_time (d: DATE_DURATION; t: TIME_DURATION)
			-- A duration of `d' and `t' (kept as they are).
		do
			date := d
			time := t
		ensure
			date_set: date = d
			time_set: time = t
		end

	make_by_date (d: DATE_DURATION)
			-- A duration of `d' and no time.
		do
			date := d
			create time.make (0, 0, 0)
		ensure
			date_set: date = d
			time_set: time.is_zero
		end

feature -- Access

	date: DATE_DURATION
			-- The years, months and days.

	time: TIME_DURATION
			-- The hours, minutes and seconds.

	origin_date_time: detachable DATE_TIME
			-- The moment the duration starts from, if set.

	year: INTEGER_32
			-- Years of the duration.
		do
			Result := date.year
		end

	month: INTEGER_32
			-- Months of the duration.
		do
			Result := date.month
		end

	day: INTEGER_32
			-- Days of the duration.
		do
			Result := date.day
		end

	hour: INTEGER_32
			-- Hours of the duration.
		do
			Result := time.hour
		end

	minute: INTEGER_32
			-- Minutes of the duration.
		do
			Result := time.minute
		end

	second: INTEGER_32
			-- Whole seconds of the duration.
		do
			Result := time.second
		end

	fine_second: REAL_64
			-- Seconds of the duration, with their fraction.
		do
			Result := time.fine_second
		end

	fractional_second: REAL_64
			-- Fraction of a second of the duration.
		do
			Result := time.fractional_second
		end

	seconds_count: INTEGER_64
			-- Length of the duration in seconds, fraction dropped.
		require
			has_origin_or_definite: has_origin_date_time or definite
		do
			Result := date.days_count.to_integer_64 * Seconds_in_day + time.seconds_count
		end

	fine_seconds_count: REAL_64
			-- Length of the duration in seconds.
		require
			has_origin_or_definite: has_origin_date_time or definite
		do
			Result := date.days_count.to_double * Seconds_in_day + time.fine_seconds_count
		end

	zero: DATE_TIME_DURATION
			-- The empty duration.
		do
			create Result.make_definite (0, 0, 0, 0)
		end

feature -- Comparison

	is_less alias "<" (other: like Current): BOOLEAN
			-- Are both durations definite and the current one shorter?
		do
			if definite and other.definite then
				Result := day + time.to_days < other.day + other.time.to_days or else
					(day + time.to_days = other.day + other.time.to_days and then
					time.time_modulo_day < other.time.time_modulo_day)
			end
		ensure then
			non_definite_result: not (definite and other.definite) implies not Result
		end

	is_equal (other: like Current): BOOLEAN
			-- Do the durations have the same years and months, and the same days and time
			-- once whole days of time are counted as days?
		do
			Result := year = other.year and month = other.month and then
				(day + time.to_days = other.day + other.time.to_days and then
				time.time_modulo_day.is_equal (other.time.time_modulo_day))
		end

feature -- Status report

	definite: BOOLEAN
			-- Are there no years and no months?
		do
			Result := date.definite
		ensure
			definition: Result = (year = 0 and month = 0)
		end

	has_origin_date_time: BOOLEAN
			-- Is `origin_date_time' set?
		do
			Result := origin_date_time /= Void
		end

	is_positive: BOOLEAN
			-- Are both the date and the time parts positive?
		do
			Result := date.is_positive and time.is_positive
		end

	canonical (start_date: DATE_TIME): BOOLEAN
			-- Is the duration written minimally for starting from `start_date': date part
			-- canonical, time part canonical, less than a day, and of the same sign?
		local
			l_final: DATE_TIME
		do
			l_final := start_date + Current
			if l_final >= start_date then
				Result := date.canonical (start_date.date) and then
					(time.seconds_count >= 0 and time.canonical and hour < Hours_in_day)
			else
				Result := date.canonical (start_date.date) and then
					(time.seconds_count <= 0 and time.canonical and hour > - Hours_in_day)
			end
		end

feature -- Status setting

	set_origin_date_time (dt: detachable DATE_TIME)
			-- Make `dt' the moment the duration starts from.
		do
			origin_date_time := dt
			if attached dt as l_dt then
				date.set_origin_date (l_dt.date)
			else
				date.set_origin_date (Void)
			end
		ensure
			origin_date_time_set: origin_date_time = dt
		end

feature -- Element change

	set_date (d: DATE_DURATION)
			-- Make `d' the date part.
		do
			date := d
		ensure
			date_set: date = d
		end

	set_time (t: TIME_DURATION)
			-- Make `t' the time part.
		do
			time := t
		ensure
			time_set: time = t
		end

	day_add (d: INTEGER_32)
			-- Add `d' days.
		do
			date.day_add (d)
		ensure
			day_set: day = old day + d
		end

feature -- Duplication

	copy (other: like Current)
			-- Take the parts and origin of `other', in objects of its own.
		do
			if other /= Current then
				standard_copy (other)
				date := other.date.twin
				time := other.time.twin
			end
		end

feature -- Basic operations

	plus alias "+" (other: like Current): like Current
			-- Sum of the duration and `other', part by part (same origin).
		do
			Result := twin
			Result.set_date (date + other.date)
			Result.set_time (time + other.time)
		end

	minus alias "-" (other: like Current): like Current
			-- The duration less `other', part by part (same origin).
		do
			Result := Current + (- other)
		end

	opposite alias "-": like Current
			-- The duration with every part negated (same origin).
		do
			Result := twin
			Result.set_date (- date)
			Result.set_time (- time)
		end

feature -- Conversion

	to_canonical (start_date: DATE_TIME): like Current
			-- The duration that leads from `start_date' to the same moment as this one,
			-- written minimally (see `canonical').
		local
			l_final: DATE_TIME
			l_time: TIME_DURATION
			l_date: DATE_DURATION
		do
			l_final := start_date + Current
			create l_time.make_fine (l_final.hour - start_date.hour, l_final.minute - start_date.minute,
				l_final.fine_second - start_date.fine_second)
			if l_final >= start_date and l_final.time < start_date.time then
				l_time.hour_add (Hours_in_day)
				l_final.day_add (-1)
			elseif l_final < start_date and l_final.time > start_date.time then
				l_time.hour_add (- Hours_in_day)
				l_final.day_add (1)
			end
			create l_date.make_by_days (l_final.days - start_date.days)
			Result := twin
			Result.set_origin_date_time (Void)
			Result.set_date (l_date.to_canonical (start_date.date))
			Result.set_time (l_time.to_canonical)
		end

	time_to_canonical: like Current
			-- The same definite duration with whole days of time moved into `day', the
			-- time part canonical and of the sign of the whole.
		require
			definite_duration: definite
		local
			l_seconds: REAL_64
			l_days: INTEGER_32
		do
			l_seconds := date.day.to_double * Seconds_in_day + time.fine_seconds_count
			Result := twin
			if l_seconds >= 0 then
				l_days := (l_seconds / Seconds_in_day).floor
			else
				l_days := - ((- l_seconds) / Seconds_in_day).floor
			end
			Result.date.make_by_days (l_days)
			Result.set_time ((create {TIME_DURATION}.make_by_fine_seconds (l_seconds - l_days.to_double * Seconds_in_day)).to_canonical)
		ensure
			time_canonical: Result.time.canonical
		end

invariant
	origin_consistent: attached origin_date_time as o implies date.origin_date = o.date

end
