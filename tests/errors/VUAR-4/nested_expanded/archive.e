note
	description: "An archive of readings."

class
	ARCHIVE

create
	make

feature {NONE} -- Initialization

	make
			-- Empty archive.
		do
			count := 0
		end

feature -- Access

	count: INTEGER
			-- Readings archived.

	last_stamp: INTEGER
			-- Time stamp archived last.

	has_origin: BOOLEAN
			-- Was an origin archived?

feature -- Element change

	store (a_stamped: STAMPED_READING)
			-- Archive `a_stamped'.
		do
			count := count + 1
			last_stamp := a_stamped.stamp
		end

	store_stamp (a_stamp: INTEGER)
			-- Archive a reading taken at `a_stamp'.
		do
			count := count + 1
			last_stamp := a_stamp
		end

	store_origin (a_origin: ORIGIN_TAG)
			-- Archive where a reading comes from.
		do
			has_origin := attached a_origin.source
		end

end
