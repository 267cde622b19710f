note
	description: "Looks at the latest entry of an archive."

class
	ARCHIVE_VIEWER

create
	make

feature {NONE} -- Initialization

	make
			-- Create an archive and look at it.
		local
			l_archive: separate ARCHIVE
		do
			create l_archive.make
			view (l_archive)
		end

feature -- Basic operations

	view (a_archive: separate ARCHIVE)
			-- Print the latest entry of `a_archive'.
		local
			l_stamped: STAMPED_READING
			l_origin: ORIGIN_TAG
		do
			l_stamped := a_archive.latest -- E: VUER
			l_origin := a_archive.latest_origin
			print (a_archive.latest_stamp)
			print (l_stamped.stamp)
			if attached l_origin.source then
				print ("origin known%N")
			end
		end

end
