note
	description: "Writes numbered lines into a shared log."

class
	WRITER

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER; a_log: separate MISSION_LOG; a_count: INTEGER)
			-- Writer `an_id' who will add `a_count' lines to `a_log'.
		do
			id := an_id
			log := a_log
			line_count := a_count
		end

feature -- Access

	id: INTEGER
			-- Writer number.

	line_count: INTEGER
			-- Lines to write.

feature -- Basic operations

	write_all
			-- Write every line.
		local
			i: INTEGER
			l_line: STRING
		do
			from
				i := 1
			until
				i > line_count
			loop
				l_line := "writer " + id.out + ", line " + i.out
				write (log, l_line)
				i := i + 1
			end
		end

feature {NONE} -- Implementation

	write (a_log: separate MISSION_LOG; a_line: STRING)
			-- Append `a_line' to `a_log'.
		do
			a_log.add_line (a_line)
		ensure
			written: a_log.version = old a_log.version + 1
		end

	log: separate MISSION_LOG
			-- The shared log.

end
