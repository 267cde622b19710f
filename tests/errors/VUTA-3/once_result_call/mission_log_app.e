note
	description: "Writes to a log shared by the whole program."

class
	MISSION_LOG_APP

create
	make

feature {NONE} -- Initialization

	make
			-- Log the start of the mission.
		do
			write (shared_log, 1)
		end

feature -- Access

	shared_log: separate EVENT_LOG
			-- The log of the whole program, with a first entry.
		once ("PROCESS")
			create Result.make
			Result.add_entry (0) -- E: VUTA(3)
		end

feature -- Basic operations

	write (a_log: separate EVENT_LOG; a_code: INTEGER)
			-- Log `a_code' in `a_log'.
		do
			a_log.add_entry (a_code)
		ensure
			logged: a_log.entries.count = old a_log.entries.count + 1
		end

end
