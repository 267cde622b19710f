note
	description: "Plans waypoints and saves them on a recorder."

class
	MISSION

create
	make

feature {NONE} -- Initialization

	make
			-- Plan two waypoints and save them.
		local
			l_recorder: separate RECORDER
		do
			create waypoints.make (4)
			waypoints.extend (10)
			waypoints.extend (20)
			create l_recorder.make
			save (l_recorder)
		end

feature -- Basic operations

	save (a_recorder: separate RECORDER)
			-- Save `waypoints' on `a_recorder'.
		do
			a_recorder.store (waypoints) -- E: VUAR(3)
			a_recorder.store_separate (waypoints)
			a_recorder.store_count (waypoints.count)
		end

feature -- Access

	waypoints: ARRAYED_LIST [INTEGER]
			-- Waypoints planned.

end
