note
	description: "Tracks targets with a camera."

class
	TRACKER

create
	make

feature {NONE} -- Initialization

	make
			-- Tracker that has seen one target.
		do
			target_count := 1
		end

feature -- Access

	target_count: INTEGER
			-- Number of targets seen.

	current_target: TARGET_INFO
			-- The target tracked now.
		do
			Result.set ("ball", 120)
		end

end
