note
	description: "[
		A shared document of a fixed number of lines. A writer rewrites it with several calls
		(start a revision, then add each line), so between two of those calls it is
		incomplete: every line is stamped with the revision that wrote it.
	]"

class
	DOCUMENT

create
	make

feature {NONE} -- Initialization

	make (a_line_count: INTEGER)
			-- Document of `a_line_count' lines, at revision 0.
		require
			some_lines: a_line_count > 0
		do
			line_count := a_line_count
			create stamps.make (a_line_count)
			across 1 |..| a_line_count as i loop
				stamps.extend (0)
			end
		ensure
			first_revision: revision = 0
			complete: is_complete
		end

feature -- Access

	revision: INTEGER
			-- Number of revisions started so far.

	line_count: INTEGER
			-- Lines in a complete revision.

	line_revision (i: INTEGER): INTEGER
			-- Revision that wrote line `i'.
		require
			valid_line: 1 <= i and i <= written_count
		do
			Result := stamps.i_th (i)
		end

	written_count: INTEGER
			-- Number of lines written so far (exported: the precondition of `line_revision' uses it).
		do
			Result := stamps.count
		end

feature -- Status report

	is_complete: BOOLEAN
			-- Does the document have all its lines?
		do
			Result := stamps.count = line_count
		end

feature -- Element change

	begin_revision
			-- Start a new revision: clear every line.
		require
			previous_complete: is_complete
		do
			revision := revision + 1
			stamps.wipe_out
		ensure
			new_revision: revision = old revision + 1
			cleared: stamps.is_empty
		end

	add_line
			-- Append a line of the current revision.
		require
			not_complete: not is_complete
		do
			stamps.extend (revision)
		ensure
			one_more_line: stamps.count = old stamps.count + 1
		end

feature {NONE} -- Implementation

	stamps: ARRAYED_LIST [INTEGER]
			-- Revision that wrote each line, first line first.

invariant
	not_too_long: stamps.count <= line_count
	no_future_line: across stamps is s all s <= revision end

end
