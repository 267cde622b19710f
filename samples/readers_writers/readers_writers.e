note
	description: "[
		Readers and writers sharing a document: each writer rewrites it line by line within
		one reservation, each reader reads it whole within one; readers wait for new
		revisions with a wait condition.
	]"

class
	READERS_WRITERS

create
	make

feature {NONE} -- Initialization

	make
			-- Start the writers and readers on one shared document, then report.
		local
			l_document: separate DOCUMENT
			l_writer: separate WRITER
			l_reader: separate READER
			i: INTEGER
		do
			create l_document.make (Line_count)
			from
				i := 1
			until
				i > Reader_count
			loop
				create l_reader.make (i, l_document, Writer_count * Edits_per_writer)
				start_reader (l_reader)
				i := i + 1
			end
			from
				i := 1
			until
				i > Writer_count
			loop
				create l_writer.make (i, l_document, Edits_per_writer)
				start_writer (l_writer)
				i := i + 1
			end
			report (l_document)
		end

feature {NONE} -- Implementation

	start_writer (a_writer: separate WRITER)
			-- Let `a_writer' write its revisions.
		do
			a_writer.write_all
		end

	start_reader (a_reader: separate READER)
			-- Let `a_reader' follow the document.
		do
			a_reader.follow
		end

	report (a_document: separate DOCUMENT)
			-- Once every revision is written, describe the document.
		require
			all_written: a_document.revision = Writer_count * Edits_per_writer
		do
			print ("Document: revision " + a_document.revision.out + ", " + a_document.line_count.out + " lines%N")
		ensure
			complete: a_document.is_complete
		end

	Writer_count: INTEGER = 2
			-- Number of writers.

	Reader_count: INTEGER = 3
			-- Number of readers.

	Edits_per_writer: INTEGER = 3
			-- Revisions each writer writes.

	Line_count: INTEGER = 4
			-- Lines of the document.

end
