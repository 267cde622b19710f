note
	description: "Records how many waypoints a mission has."

class
	RECORDER

create
	make

feature {NONE} -- Initialization

	make
			-- Recorder with nothing recorded.
		do
			last_count := 0
		end

feature -- Access

	last_count: INTEGER
			-- Number of waypoints recorded last.

feature -- Element change

	store (a_points: ARRAYED_LIST [INTEGER])
			-- Record `a_points'.
		do
			last_count := a_points.count
		end

	store_separate (a_points: separate ARRAYED_LIST [INTEGER])
			-- Record `a_points', wherever they are.
		do
			last_count := a_points.count
		end

	store_count (n: INTEGER)
			-- Record that there are `n' waypoints.
		do
			last_count := n
		end

end
