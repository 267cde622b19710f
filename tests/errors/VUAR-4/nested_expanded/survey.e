note
	description: "Sends time-stamped readings to an archive."

class
	SURVEY

create
	make

feature {NONE} -- Initialization

	make
			-- Take a reading and archive it.
		local
			l_archive: separate ARCHIVE
			l_stamped: STAMPED_READING
			l_origin: ORIGIN_TAG
		do
			create l_archive.make
			l_stamped.set_stamp (17)
			l_origin.set_source ("north station")
			archive (l_archive, l_stamped, l_origin)
		end

feature -- Basic operations

	archive (a_archive: separate ARCHIVE; a_stamped: STAMPED_READING; a_origin: ORIGIN_TAG)
			-- Archive `a_stamped', which comes from `a_origin', in `a_archive'.
		do
			a_archive.store (a_stamped) -- E: VUAR(4)
			a_archive.store_stamp (a_stamped.stamp)
			a_archive.store_origin (a_origin)
		end

end
