note
	description: "The last known position of the ball, with a version that grows at every update."

class
	BALL_SIGNALER

create
	make

feature {NONE} -- Initialization

	make
			-- Ball not seen yet, straight ahead.
		do
			y := 1.0
		ensure
			not_seen: version = 0
		end

feature -- Access

	x: REAL_64
			-- Sideways offset of the ball, in metres (positive to the left).

	y: REAL_64
			-- Distance ahead of the robot, in metres.

	version: INTEGER
			-- Number of updates so far.

feature -- Element change

	update (a_x, a_y: REAL_64)
			-- The ball was seen at (`a_x', `a_y').
		require
			ahead: a_y > 0.0
		do
			x := a_x
			y := a_y
			version := version + 1
		ensure
			new_version: version = old version + 1
		end

end
