note
	description: "Where the ball is, once it is visible (a signaler: read in wait conditions)."

class
	BALL_SIGNALER

create
	make

feature {NONE} -- Initialization

	make
			-- No ball in sight.
		do
			create clock.make
		end

feature -- Access

	x, y: REAL_64
			-- Position of the ball: metres ahead, metres to the left.

feature -- Status report

	is_visible: BOOLEAN
			-- Is the ball in sight?

feature -- Element change

	show (a_x, a_y: REAL_64)
			-- The ball appears at (`a_x', `a_y').
		do
			x := a_x
			y := a_y
			is_visible := True
			print ("Ball visible at " + clock.now.rounded.out + " s%N")
		ensure
			visible: is_visible
		end

feature {NONE} -- Implementation

	clock: TIMER
			-- The runtime's clock.

end
