note
	description: "Rewrites a shared document a few times, each time with one reservation of it."

class
	WRITER

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER; a_document: separate DOCUMENT; an_edits: INTEGER)
			-- Writer `an_id' who will rewrite `a_document' `an_edits' times.
		require
			some_edits: an_edits > 0
		do
			id := an_id
			document := a_document
			edit_count := an_edits
		end

feature -- Access

	id: INTEGER
			-- Writer number.

	edit_count: INTEGER
			-- Revisions to write.

	edits_done: INTEGER
			-- Revisions written so far.

feature -- Basic operations

	write_all
			-- Write every revision, pausing in between.
		do
			from
			until
				edits_done = edit_count
			loop
				(create {EXECUTION_ENVIRONMENT}).sleep (Pause)
				rewrite (document)
			end
		end

feature {NONE} -- Implementation

	rewrite (a_document: separate DOCUMENT)
			-- Write a new revision of `a_document', line by line.
		do
			a_document.begin_revision
			from
			until
				a_document.is_complete
			loop
				a_document.add_line
			end
			edits_done := edits_done + 1
			print ("Writer " + id.out + ": edit " + edits_done.out + " of " + edit_count.out + " written%N")
		ensure
			one_more_revision: a_document.revision = old a_document.revision + 1
			complete: a_document.is_complete
		end

	document: separate DOCUMENT
			-- The shared document.

	Pause: INTEGER_64 = 4_000_000
			-- Time between two edits, in nanoseconds.

end
