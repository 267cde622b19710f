note
	description: "An archive of time-stamped readings."

class
	ARCHIVE

create
	make

feature {NONE} -- Initialization

	make
			-- Archive with one entry.
		do
			latest.set_stamp (5)
		end

feature -- Access

	latest: STAMPED_READING
			-- The entry archived last.

	latest_origin: ORIGIN_TAG
			-- Where it comes from.

	latest_stamp: INTEGER
			-- When it was taken.
		do
			Result := latest.stamp
		end

end
