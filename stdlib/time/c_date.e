note
	description: "[
		The current date and time of day, read from the system clock when the object is
		created and again at each `update' (local time, or UTC for `make_utc').
	]"
	implementation: "[
		The clock and the calendar are the host's (`external "Python"'); the runtime's
		clock is used, so virtual time in tests moves C_DATE too.
	]"

class
	C_DATE

inherit
	ANY
		redefine
			default_create
		end

create
	default_create,
	make_utc,
	make_now,
	make_now_utc

feature {NONE} -- Initialization

	default_create
			-- Date and time now, in local time.
		do
			is_utc := False
			update
		end

	make_utc
			-- Date and time now, in UTC.
		do
			is_utc := True
			update
		ensure
			is_utc: is_utc
		end

	make_now
			-- Date and time now, in local time.
		do
			default_create
		end

	make_now_utc
			-- Date and time now, in UTC.
		do
			make_utc
		ensure
			is_utc: is_utc
		end

feature -- Access

	is_utc: BOOLEAN
			-- Are the values in UTC (rather than local time)?

	year_now: INTEGER_32
			-- Year, at creation or at the last `update'.
		do
			Result := field (timestamp, is_utc, 1)
		end

	month_now: INTEGER_32
			-- Month (1 to 12), at creation or at the last `update'.
		do
			Result := field (timestamp, is_utc, 2)
		end

	day_now: INTEGER_32
			-- Day of the month (1 to 31), at creation or at the last `update'.
		do
			Result := field (timestamp, is_utc, 3)
		end

	hour_now: INTEGER_32
			-- Hour (0 to 23), at creation or at the last `update'.
		do
			Result := field (timestamp, is_utc, 4)
		end

	minute_now: INTEGER_32
			-- Minute (0 to 59), at creation or at the last `update'.
		do
			Result := field (timestamp, is_utc, 5)
		end

	second_now: INTEGER_32
			-- Second (0 to 59), at creation or at the last `update'.
		do
			Result := field (timestamp, is_utc, 6)
		end

	millisecond_now: INTEGER_32
			-- Millisecond (0 to 999), at creation or at the last `update'.
		do
			Result := field (timestamp, is_utc, 7)
		end

feature -- Update

	update
			-- Read the clock again.
		do
			timestamp := current_timestamp
		end

feature {NONE} -- Implementation

	timestamp: REAL_64
			-- Seconds since 1970-01-01 00:00 UTC, at creation or at the last `update'.

	current_timestamp: REAL_64
			-- Seconds since 1970-01-01 00:00 UTC, now.
		external
			"Python"
		end

	field (a_timestamp: REAL_64; a_utc: BOOLEAN; a_index: INTEGER_32): INTEGER_32
			-- Field `a_index' (1 year, 2 month, 3 day, 4 hour, 5 minute, 6 second,
			-- 7 millisecond) of the date at `a_timestamp', in UTC if `a_utc', local time otherwise.
		external
			"Python"
		end

end
