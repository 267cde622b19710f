note
	description: "[
		Reads every line of a shared document each time it has a new revision, until the last
		one; since a writer holds the document for a whole revision, a reader never sees a
		revision half written.
	]"

class
	READER

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER; a_document: separate DOCUMENT; a_last_revision: INTEGER)
			-- Reader `an_id' following `a_document' up to `a_last_revision'.
		require
			positive_last: a_last_revision > 0
		do
			id := an_id
			document := a_document
			last_revision := a_last_revision
		end

feature -- Access

	id: INTEGER
			-- Reader number.

	last_revision: INTEGER
			-- Revision after which the reader stops.

	last_seen: INTEGER
			-- Revision read last.

feature -- Basic operations

	follow
			-- Read each new revision up to `last_revision'.
		do
			from
			until
				last_seen = last_revision
			loop
				read (document)
			end
			print ("Reader " + id.out + ": read up to revision " + last_seen.out + ", every revision read was whole%N")
		end

feature {NONE} -- Implementation

	read (a_document: separate DOCUMENT)
			-- Once `a_document' has a revision not read yet, read all its lines.
		require
			something_new: a_document.revision > last_seen
		local
			l_matching: INTEGER
		do
			last_seen := a_document.revision
			across 1 |..| a_document.line_count as i loop
				if a_document.line_revision (i.item) = last_seen then
					l_matching := l_matching + 1
				end
			end
			check
				whole_revision: l_matching = a_document.line_count
			end
		ensure
			complete: a_document.is_complete
			caught_up: last_seen = a_document.revision
		end

	document: separate DOCUMENT
			-- The shared document.

invariant
	not_beyond_last: last_seen <= last_revision

end
