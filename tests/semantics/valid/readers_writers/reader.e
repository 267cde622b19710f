note
	description: "Reads each new version of a shared log until it has a given number of lines."

class
	READER

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER; a_log: separate MISSION_LOG; a_final_version: INTEGER)
			-- Reader `an_id' following `a_log' up to `a_final_version'.
		do
			id := an_id
			log := a_log
			final_version := a_final_version
			last_line := ""
		end

feature -- Access

	id: INTEGER
			-- Reader number.

	last_seen: INTEGER
			-- Version of the log read last.

	final_version: INTEGER
			-- Version after which the reader stops.

	last_line: STRING
			-- Copy of the newest line read.

feature -- Basic operations

	follow
			-- Read every new version of the log up to `final_version'.
		do
			from
			until
				last_seen >= final_version
			loop
				read (log)
			end
			print ("Reader " + id.out + " is done; last line: " + last_line + "%N")
		end

feature {NONE} -- Implementation

	read (a_log: separate MISSION_LOG)
			-- Read `a_log' once it has a version not seen yet.
		require
			something_new: a_log.version > last_seen
		do
			last_seen := a_log.version
			create last_line.make_from_separate (a_log.lines.last)
			print ("Reader " + id.out + " sees " + a_log.lines.count.out + " lines, " + total_length (a_log.lines).out + " characters, longest " + longest (a_log.lines).out + "%N")
		ensure
			caught_up: last_seen = a_log.version
		end

	total_length (a_lines: separate ARRAYED_LIST [STRING]): INTEGER
			-- Number of characters in `a_lines'.
		do
			across a_lines as c loop
				Result := Result + c.item.count
			end
		end

	longest (a_lines: separate ARRAYED_LIST [STRING]): INTEGER
			-- Length of the longest line in `a_lines'.
		do
			across a_lines is l_line loop
				if l_line.count > Result then
					Result := l_line.count
				end
			end
		ensure
			non_negative: Result >= 0
		end

	log: separate MISSION_LOG
			-- The shared log.

end
