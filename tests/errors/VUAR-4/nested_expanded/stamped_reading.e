note
	description: "A reading with the time it was taken, copied on assignment."

expanded class
	STAMPED_READING

feature -- Access

	reading: READING
			-- The reading.

	stamp: INTEGER
			-- When it was taken, in seconds since the start.

feature -- Element change

	set_stamp (a_stamp: INTEGER)
			-- Set `stamp' to `a_stamp'.
		do
			stamp := a_stamp
		end

end
