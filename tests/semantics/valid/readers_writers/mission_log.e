note
	description: "A log of text lines with a version number that grows with every line."

class
	MISSION_LOG

create
	make

feature {NONE} -- Initialization

	make
			-- Empty log.
		do
			create lines.make (10)
		ensure
			no_line: lines.is_empty
		end

feature -- Access

	lines: ARRAYED_LIST [STRING]
			-- The lines, oldest first.

	version: INTEGER
			-- Number of lines added so far.

feature -- Element change

	add_line (a_line: separate STRING)
			-- Append a copy of `a_line'.
		do
			lines.extend (create {STRING}.make_from_separate (a_line))
			version := version + 1
		ensure
			one_more_line: lines.count = old lines.count + 1
			new_version: version = old version + 1
		end

invariant
	version_counts_lines: version = lines.count

end
