note
	description: "[
		The calendar's rules (Gregorian): lengths of months and years, leap years, the
		names of days and months, and the rule for a correct date.
	]"

class
	DATE_CONSTANTS

inherit
	TIME_UTILITY

feature -- Access

	Days_in_week: INTEGER_32 = 7
			-- Number of days in a week.

	Max_weeks_in_year: INTEGER_32 = 53
			-- Largest number of (possibly partial) weeks in a year.

	Months_in_year: INTEGER_32 = 12
			-- Number of months in a year.

	Days_in_leap_year: INTEGER_32 = 366
			-- Number of days in a leap year.

	Days_in_non_leap_year: INTEGER_32 = 365
			-- Number of days in other years.

	date_default_format_string: STRING_8 = "[0]mm/[0]dd/yyyy"
			-- How `out' writes a date: month and day on two digits, year on four.

	days_in_i_th_month (i, y: INTEGER_32): INTEGER_32
			-- Number of days of month `i' in year `y'.
		require
			i_large_enough: i >= 1
			i_small_enough: i <= Months_in_year
		do
			inspect i
			when 2 then
				if is_leap_year (y) then
					Result := 29
				else
					Result := 28
				end
			when 4, 6, 9, 11 then
				Result := 30
			else
				Result := 31
			end
		end

	days_text: ARRAY [STRING_8]
			-- Short names of the days of the week, Sunday first.
		do
			Result := <<"SUN", "MON", "TUE", "WED", "THU", "FRI", "SAT">>
			Result.compare_objects
		end

	long_days_text: ARRAY [STRING_8]
			-- Names of the days of the week, Sunday first.
		do
			Result := <<"SUNDAY", "MONDAY", "TUESDAY", "WEDNESDAY", "THURSDAY", "FRIDAY", "SATURDAY">>
			Result.compare_objects
		end

	months_text: ARRAY [STRING_8]
			-- Short names of the months, January first.
		do
			Result := <<"JAN", "FEB", "MAR", "APR", "MAY", "JUN", "JUL", "AUG", "SEP", "OCT", "NOV", "DEC">>
			Result.compare_objects
		end

	long_months_text: ARRAY [STRING_8]
			-- Names of the months, January first.
		do
			Result := <<"JANUARY", "FEBRUARY", "MARCH", "APRIL", "MAY", "JUNE", "JULY",
				"AUGUST", "SEPTEMBER", "OCTOBER", "NOVEMBER", "DECEMBER">>
			Result.compare_objects
		end

feature -- Status report

	is_leap_year (y: INTEGER_32): BOOLEAN
			-- Has year `y' 366 days?
		do
			Result := mod (y, 4) = 0 and (mod (y, 100) /= 0 or mod (y, 400) = 0)
		end

	is_correct_date (y, m, d: INTEGER_32): BOOLEAN
			-- Is day `d' of month `m' of year `y' a date this library can hold (years 0 to 65535)?
		do
			Result := m >= 1 and m <= Months_in_year and then
				(d >= 1 and d <= days_in_i_th_month (m, y) and y >= 0 and y <= 65535)
		end

end
