note
	description: "Lengths of the units of a day, and the rule for a correct time of day."

class
	TIME_CONSTANTS

feature -- Access

	Seconds_in_day: INTEGER_32 = 86400
			-- Number of seconds in a day.

	Seconds_in_hour: INTEGER_32 = 3600
			-- Number of seconds in an hour.

	Seconds_in_minute: INTEGER_32 = 60
			-- Number of seconds in a minute.

	Minutes_in_hour: INTEGER_32 = 60
			-- Number of minutes in an hour.

	Hours_in_day: INTEGER_32 = 24
			-- Number of hours in a day.

feature -- Status report

	is_correct_time (h, m: INTEGER_32; s: REAL_64; twelve_hour_scale: BOOLEAN): BOOLEAN
			-- Is `h':`m':`s' a time of day (`h' from 1 to 12 if `twelve_hour_scale')?
		do
			if twelve_hour_scale then
				Result := h >= 1 and h <= 12
			else
				Result := h >= 0 and h < Hours_in_day
			end
			Result := Result and (m >= 0 and m < Minutes_in_hour) and (s >= 0.0 and s < Seconds_in_minute)
		end

end
