note
	description: "Writers append lines to a shared mission log while readers follow its new versions."

class
	READERS_WRITERS

create
	make

feature {NONE} -- Initialization

	make
			-- Start the writers and readers on one shared log.
		local
			l_log: separate MISSION_LOG
			l_writer: separate WRITER
			l_reader: separate READER
			i: INTEGER
		do
			create l_log.make
			from
				i := 1
			until
				i > Writer_count
			loop
				create l_writer.make (i, l_log, Lines_per_writer)
				start_writer (l_writer)
				i := i + 1
			end
			from
				i := 1
			until
				i > Reader_count
			loop
				create l_reader.make (i, l_log, Writer_count * Lines_per_writer)
				start_reader (l_reader)
				i := i + 1
			end
		end

feature {NONE} -- Implementation

	start_writer (a_writer: separate WRITER)
			-- Let `a_writer' write its lines.
		do
			a_writer.write_all
		end

	start_reader (a_reader: separate READER)
			-- Let `a_reader' follow the log.
		do
			a_reader.follow
		end

	Writer_count: INTEGER = 2
			-- Number of writers.

	Reader_count: INTEGER = 3
			-- Number of readers.

	Lines_per_writer: INTEGER = 4
			-- Lines each writer adds.

end
