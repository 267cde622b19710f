note
	description: "[
		Where the ball is, as the robot's camera last saw it: a signaler, read by the
		controllers in their wait conditions.
	]"

class
	BALL_SIGNALER

create
	make

feature {NONE} -- Initialization

	make
			-- Ball straight ahead, no position published yet.
		do
			bearing := 0
		ensure
			ahead: bearing = 0
			nothing_published: version = 0
			in_play: not is_gone
		end

feature -- Access

	bearing: INTEGER
			-- Direction of the ball, in degrees (positive to the left).

	version: INTEGER
			-- Number of positions published so far.

feature -- Status report

	is_gone: BOOLEAN
			-- Has the ball been put away, so that no more positions will come?

feature -- Element change

	publish (a_bearing: INTEGER)
			-- The ball was seen at `a_bearing'.
		require
			in_play: not is_gone
		do
			bearing := a_bearing
			version := version + 1
		ensure
			bearing_set: bearing = a_bearing
			new_version: version = old version + 1
		end

	put_away
			-- The ball leaves the game.
		require
			in_play: not is_gone
		do
			is_gone := True
		ensure
			gone: is_gone
		end

invariant
	non_negative_version: version >= 0

end
