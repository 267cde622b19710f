note
	description: "[
		Days of the Gregorian calendar, years 0 to 65535: year, month, day, the day of the
		week, arithmetic in days, months and years. Dates are ordered; `out' writes
		"mm/dd/yyyy" (month and day on two digits).
	]"
	implementation: "Plain Eiffel; `make_now' reads the clock through C_DATE."

class
	DATE

inherit
	COMPARABLE
		redefine
			out
		end

	DATE_CONSTANTS
		undefine
			is_equal,
			out
		end

create
	make,
	make_month_day_year,
	make_day_month_year,
	make_now,
	make_now_utc,
	make_by_days

feature -- Initialization

	make (y, m, d: INTEGER_32)
			-- Day `d' of month `m' of year `y'.
		require
			correct_date: is_correct_date (y, m, d)
		do
			year := y
			month := m
			day := d
		ensure
			year_set: year = y
			month_set: month = m
			day_set: day = d
		end

	make_month_day_year (m, d, y: INTEGER_32)
			-- Day `d' of month `m' of year `y'.
		require
			correct_date: is_correct_date (y, m, d)
		do
			make (y, m, d)
		ensure
			year_set: year = y
			month_set: month = m
			day_set: day = d
		end

	make_day_month_year (d, m, y: INTEGER_32)
			-- Day `d' of month `m' of year `y'.
		require
			correct_date: is_correct_date (y, m, d)
		do
			make (y, m, d)
		ensure
			year_set: year = y
			month_set: month = m
			day_set: day = d
		end

	make_now
			-- Today, in local time.
		local
			l_now: C_DATE
		do
			create l_now
			make (l_now.year_now, l_now.month_now, l_now.day_now)
		end

	make_now_utc
			-- Today, in UTC.
		local
			l_now: C_DATE
		do
			create l_now.make_utc
			make (l_now.year_now, l_now.month_now, l_now.day_now)
		end

	make_by_days (n: INTEGER_32)
			-- The date `n' days after `origin' (before it if `n' is negative).
		local
			l_days, l_era, l_day_of_era, l_year_of_era, l_day_of_year, l_shifted_month: INTEGER_32
		do
				-- Count from 0000-03-01, so that a leap day ends its year.
			l_days := n + Days_from_march_0000_to_origin
			l_era := div (l_days, Days_in_400_years)
			l_day_of_era := l_days - l_era * Days_in_400_years
			l_year_of_era := (l_day_of_era - l_day_of_era // 1460 + l_day_of_era // 36524 - l_day_of_era // 146096) // 365
			l_day_of_year := l_day_of_era - (365 * l_year_of_era + l_year_of_era // 4 - l_year_of_era // 100)
			l_shifted_month := (5 * l_day_of_year + 2) // 153
			day := l_day_of_year - (153 * l_shifted_month + 2) // 5 + 1
			if l_shifted_month < 10 then
				month := l_shifted_month + 3
				year := l_era * 400 + l_year_of_era
			else
				month := l_shifted_month - 9
				year := l_era * 400 + l_year_of_era + 1
			end
		ensure
			days_set: days = n
		end

feature -- Access

	year: INTEGER_32
			-- Year.

	month: INTEGER_32
			-- Month (1 to 12).

	day: INTEGER_32
			-- Day of the month.

	origin: DATE
			-- The date days are counted from: 1600-01-01.
		do
			create Result.make (1600, 1, 1)
		end

feature -- Measurement

	days: INTEGER_32
			-- Number of days since `origin' (negative before it).
		local
			l_year, l_era, l_year_of_era, l_day_of_year: INTEGER_32
		do
			l_year := year
			if month <= 2 then
				l_year := l_year - 1
			end
			l_era := div (l_year, 400)
			l_year_of_era := l_year - l_era * 400
			if month > 2 then
				l_day_of_year := (153 * (month - 3) + 2) // 5 + day - 1
			else
				l_day_of_year := (153 * (month + 9) + 2) // 5 + day - 1
			end
			Result := l_era * Days_in_400_years + l_year_of_era * 365 + l_year_of_era // 4 - l_year_of_era // 100
				+ l_day_of_year - Days_from_march_0000_to_origin
		end

	duration: DATE_DURATION
			-- Time since `origin', in days.
		do
			create Result.make_by_days (days)
		ensure
			definite_result: Result.definite
		end

feature -- Status report

	leap_year: BOOLEAN
			-- Is `year' a leap year?
		do
			Result := is_leap_year (year)
		end

	days_in_month: INTEGER_32
			-- Number of days of `month' in `year'.
		do
			Result := days_in_i_th_month (month, year)
		end

	days_in_year: INTEGER_32
			-- Number of days in `year'.
		do
			if leap_year then
				Result := Days_in_leap_year
			else
				Result := Days_in_non_leap_year
			end
		end

	days_at_month: INTEGER_32
			-- Number of days of the year before the first of `month'.
		local
			i: INTEGER_32
		do
			from
				i := 1
			until
				i = month
			loop
				Result := Result + days_in_i_th_month (i, year)
				i := i + 1
			end
		ensure
			positive_result: Result >= 0
		end

	year_day: INTEGER_32
			-- Position of the date in its year (1 for January 1st).
		do
			Result := days_at_month + day
		ensure
			result_large_enough: Result >= 1
			result_small_enough: Result <= days_in_year
		end

	day_of_the_week: INTEGER_32
			-- Day of the week: 1 for Sunday, 2 for Monday, ..., 7 for Saturday.
		do
				-- `origin' was a Saturday.
			Result := mod (days + 6, Days_in_week) + 1
		ensure
			day_of_the_week_range: Result >= 1 and Result <= 7
		end

	day_of_january_1st: INTEGER_32
			-- Day of the week of January 1st of `year' (1 for Sunday).
		do
			Result := (create {DATE}.make (year, 1, 1)).day_of_the_week
		ensure
			day_of_the_week_range: Result >= 1 and Result <= 7
		end

	week_of_year: INTEGER_32
			-- Number of the week in the year, weeks starting on Sunday; the days before
			-- the first Sunday of the year are in week 0.
		do
			if day_of_the_week <= year_day then
				Result := (year_day - day_of_the_week) // Days_in_week + 1
			end
		ensure
			positive_result: Result >= 0
			result_small_enough: Result < Max_weeks_in_year
		end

	days_from (y: INTEGER_32): INTEGER_32
			-- Number of days from January 1st of year `y' to January 1st of `year'.
		do
			Result := (create {DATE}.make (year, 1, 1)).days - (create {DATE}.make (y, 1, 1)).days
		end

feature -- Comparison

	is_less alias "<" (other: like Current): BOOLEAN
			-- Is the date before `other'?
		do
			Result := year < other.year or else (year = other.year and then
				(month < other.month or else (month = other.month and then day < other.day)))
		end

feature -- Element change

	set_date (y, m, d: INTEGER_32)
			-- Make the date day `d' of month `m' of year `y'.
		require
			d_large_enough: d >= 1
			m_large_enough: m >= 1
			m_small_enough: m <= Months_in_year
			d_small_enough: d <= days_in_i_th_month (m, y)
		do
			year := y
			month := m
			day := d
		ensure
			day_set: day = d
			month_set: month = m
			year_set: year = y
		end

	set_day (d: INTEGER_32)
			-- Make `d' the day of the month.
		require
			d_large_enough: d >= 1
			d_small_enough: d <= days_in_month
		do
			day := d
		ensure
			day_set: day = d
		end

	set_month (m: INTEGER_32)
			-- Make `m' the month.
		require
			m_large_enough: m >= 1
			m_small_enough: m <= Months_in_year
			d_small_enough: day <= days_in_i_th_month (m, year)
		do
			month := m
		ensure
			month_set: month = m
		end

	set_year (y: INTEGER_32)
			-- Make `y' the year.
		require
			can_not_cut_29th_feb: day <= days_in_i_th_month (month, y)
		do
			year := y
		ensure
			year_set: year = y
		end

feature -- Basic operations

	plus alias "+" (d: DATE_DURATION): DATE
			-- The date `d' later: years and months first, then days.
		do
			Result := twin
			Result.add (d)
		end

	add (d: DATE_DURATION)
			-- Move `d' later: years and months first (the day cut to the month's
			-- length if needed), then days.
		do
			if not d.definite then
				year_month_add (d.year, d.month)
			end
			day_add (d.day)
		end

	relative_duration (other: like Current): DATE_DURATION
			-- Duration from `other' to the date, in canonical form, starting from `other'.
		do
			create Result.make_by_days (days - other.days)
			Result := Result.to_canonical (other)
			Result.set_origin_date (other.twin)
		ensure
			exact_duration: other + Result ~ Current
		end

	day_forth
			-- Move to the next day.
		do
			day_add (1)
		ensure
			days_set: days = old days + 1
		end

	day_back
			-- Move to the day before.
		do
			day_add (-1)
		ensure
			days_set: days = old days - 1
		end

	day_add (d: INTEGER_32)
			-- Move `d' days later (earlier if `d' is negative).
		do
			make_by_days (days + d)
		ensure
			days_set: days = old days + d
		end

	month_forth
			-- Move to the next month (the day cut to its length if needed).
		do
			month_add (1)
		end

	month_back
			-- Move to the month before (the day cut to its length if needed).
		do
			month_add (-1)
		end

	month_add (m: INTEGER_32)
			-- Move `m' months later (earlier if `m' is negative); the day is cut
			-- to the length of the new month if needed.
		local
			l_months, l_year, l_month: INTEGER_32
		do
			l_months := month - 1 + m
			l_year := year + div (l_months, Months_in_year)
			l_month := mod (l_months, Months_in_year) + 1
			set_date (l_year, l_month, day.min (days_in_i_th_month (l_month, l_year)))
		end

	year_forth
			-- Move to the next year (February 29th becomes the 28th).
		do
			year_add (1)
		ensure
			year_increased: year = old year + 1
		end

	year_back
			-- Move to the year before (February 29th becomes the 28th).
		do
			year_add (-1)
		ensure
			year_decreased: year = old year - 1
		end

	year_add (y: INTEGER_32)
			-- Move `y' years later (earlier if `y' is negative); February 29th becomes
			-- the 28th in a year that is not leap.
		do
			set_date (year + y, month, day.min (days_in_i_th_month (month, year + y)))
		ensure
			year_set: year = old year + y
		end

	year_month_add (y, m: INTEGER_32)
			-- Move `y' years and `m' months later, the day cut to the month's length if needed.
		do
			month_add (y * Months_in_year + m)
		end

feature -- Conversion

	to_date_time: DATE_TIME
			-- The date at midnight.
		do
			create Result.make_by_date (Current)
		end

feature -- Output

	out: STRING_8
			-- The date as "mm/dd/yyyy".
		do
			create Result.make (10)
			append_padded (Result, month, 2)
			Result.append_character ('/')
			append_padded (Result, day, 2)
			Result.append_character ('/')
			append_padded (Result, year, 4)
		end

feature {NONE} -- Implementation

	Days_in_400_years: INTEGER_32 = 146097
			-- Number of days in 400 years of the Gregorian calendar.

	Days_from_march_0000_to_origin: INTEGER_32 = 584328
			-- Number of days from 0000-03-01 to 1600-01-01.

	append_padded (s: STRING_8; n, width: INTEGER_32)
			-- Append `n' to `s' with zeros before it to fill `width' digits.
		local
			l_digits: STRING_8
		do
			l_digits := n.out
			if l_digits.count < width then
				s.append (create {STRING_8}.make_filled ('0', width - l_digits.count))
			end
			s.append (l_digits)
		end

invariant
	month_large_enough: month >= 1
	month_small_enough: month <= Months_in_year
	day_large_enough: day >= 1
	day_small_enough: day <= days_in_month
	year_small_enough: year <= 65535
	year_non_negative: year >= 0

end
