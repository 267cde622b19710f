note
	description: "Logs mission events in one log shared by every processor."

class
	MISSION_CONTROL

create
	make

feature {NONE} -- Initialization

	make
			-- Log the start of the mission.
		do
			report (shared_log)
			local_log.add_entry (start_code)
			print (start_code)
		end

feature -- Access

	shared_log: separate EVENT_LOG
			-- The log of the whole program.
		once ("PROCESS")
			create Result.make
		end

	local_log: EVENT_LOG -- E: VFFD(8)
			-- A log meant for the whole program, but not separate.
		once ("PROCESS")
			create Result.make
		end

	start_code: INTEGER
			-- Code of the mission, the same for every processor.
		once ("PROCESS")
			Result := 42
		end

feature -- Basic operations

	report (a_log: separate EVENT_LOG)
			-- Log the start of the mission in `a_log'.
		do
			a_log.add_entry (start_code)
		end

end
