note
	description: "[
		Lengths of time counted in years, months and days, possibly negative. A duration
		with no years and no months is `definite' (the same number of days whatever the
		date it starts from); otherwise its length in days depends on its `origin_date'.
	]"

class
	DATE_DURATION

inherit
	DURATION
		redefine
			is_equal
		end

	DATE_CONSTANTS
		undefine
			is_equal
		end

create
	make,
	make_by_days

feature -- Initialization

	make (y, m, d: INTEGER_32)
			-- A duration of `y' years, `m' months and `d' days.
		do
			year := y
			month := m
			day := d
		ensure
			year_set: year = y
			month_set: month = m
			day_set: day = d
		end

	make_by_days (d: INTEGER_32)
			-- A duration of `d' days (definite).
		do
			year := 0
			month := 0
			day := d
		ensure
			day_set: day = d
			definite_duration: definite
		end

feature -- Access

	year: INTEGER_32
			-- Years of the duration.

	month: INTEGER_32
			-- Months of the duration.

	day: INTEGER_32
			-- Days of the duration.

	origin_date: detachable DATE
			-- The date the duration starts from, if set.

	days_count: INTEGER_32
			-- Length of the duration in days (from `origin_date' when it is not definite).
		require
			origin_date_set_or_definite: has_origin_date or definite
		do
			if attached origin_date as l_origin then
				Result := (l_origin + Current).days - l_origin.days
			else
				Result := day
			end
		end

	zero: DATE_DURATION
			-- The empty duration.
		do
			create Result.make_by_days (0)
		ensure
			definite: Result.definite
		end

feature -- Comparison

	is_less alias "<" (other: like Current): BOOLEAN
			-- Are both durations definite and the current one shorter?
		do
			Result := definite and then other.definite and then day < other.day
		ensure then
			non_definite_duration: not (definite and other.definite) implies not Result
		end

	is_equal (other: like Current): BOOLEAN
			-- Have the durations the same years, months and days?
		do
			Result := year = other.year and month = other.month and day = other.day
		end

feature -- Status report

	definite: BOOLEAN
			-- Are there no years and no months (only days)?
		do
			Result := year = 0 and month = 0
		ensure
			definition: Result = (year = 0 and month = 0)
		end

	has_origin_date: BOOLEAN
			-- Is `origin_date' set?
		do
			Result := origin_date /= Void
		end

	is_positive: BOOLEAN
			-- Is some part of the duration above zero?
		do
			Result := day > 0 or month > 0 or year > 0
		end

	is_negative: BOOLEAN
			-- Is some part below zero and none above?
		do
			Result := not is_positive and not is_zero
		end

	is_zero: BOOLEAN
			-- Are all parts zero?
		do
			Result := day = 0 and month = 0 and year = 0
		end

	canonical (a_date: DATE): BOOLEAN
			-- Is the duration written minimally for starting from `a_date': all parts of
			-- one sign, fewer than 12 months, and fewer days than would make one more month?
		local
			l_final: DATE
		do
			l_final := a_date + Current
			if l_final >= a_date then
				Result := (year >= 0 and month >= 0 and month < Months_in_year and day >= 0) and then
					l_final < a_date + create {DATE_DURATION}.make (year, month + 1, 0)
			else
				Result := (year <= 0 and month <= 0 and month > - Months_in_year and day <= 0) and then
					l_final > a_date + create {DATE_DURATION}.make (year, month - 1, 0)
			end
		end

feature -- Status setting

	set_origin_date (d: detachable DATE)
			-- Make `d' the date the duration starts from.
		do
			origin_date := d
		ensure
			origin_date_set: origin_date = d
		end

feature -- Element change

	set_year (y: INTEGER_32)
			-- Make `y' the years.
		do
			year := y
		ensure
			year_set: year = y
		end

	set_month (m: INTEGER_32)
			-- Make `m' the months.
		do
			month := m
		ensure
			month_set: month = m
		end

	set_day (d: INTEGER_32)
			-- Make `d' the days.
		do
			day := d
		ensure
			day_set: day = d
		end

	year_add (y: INTEGER_32)
			-- Add `y' years.
		do
			year := year + y
		ensure
			year_set: year = old year + y
		end

	month_add (m: INTEGER_32)
			-- Add `m' months.
		do
			month := month + m
		ensure
			month_set: month = old month + m
		end

	day_add (d: INTEGER_32)
			-- Add `d' days.
		do
			day := day + d
		ensure
			day_set: day = old day + d
		end

feature -- Basic operations

	plus alias "+" (other: like Current): like Current
			-- Sum of the duration and `other', part by part (same origin).
		do
			Result := twin
			Result.make (year + other.year, month + other.month, day + other.day)
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
			Result.make (- year, - month, - day)
		end

feature -- Conversion

	to_canonical (start_date: DATE): like Current
			-- The duration that leads from `start_date' to the same date as this one,
			-- written minimally (see `canonical').
		local
			l_final, l_date: DATE
			l_months: INTEGER_32
		do
			l_final := start_date + Current
			l_months := (l_final.year - start_date.year) * Months_in_year + l_final.month - start_date.month
			l_date := start_date.twin
			l_date.month_add (l_months)
			if l_final >= start_date and l_date > l_final then
				l_months := l_months - 1
				l_date := start_date.twin
				l_date.month_add (l_months)
			elseif l_final < start_date and l_date < l_final then
				l_months := l_months + 1
				l_date := start_date.twin
				l_date.month_add (l_months)
			end
			Result := twin
			Result.make (l_months // Months_in_year, l_months \\ Months_in_year, l_final.days - l_date.days)
			Result.set_origin_date (Void)
		ensure
			canonical_result: Result.canonical (start_date)
		end

	to_definite (a_date: DATE)
			-- Make the duration definite: the number of days it spans from `a_date'.
		do
			make_by_days ((a_date + Current).days - a_date.days)
		ensure
			definite_result: definite
		end

	to_date_time: DATE_TIME_DURATION
			-- The same duration, with no hours, minutes or seconds.
		do
			create Result.make (year, month, day, 0, 0, 0)
		ensure
			year_set: Result.year = year
			month_set: Result.month = month
			day_set: Result.day = day
		end

end
