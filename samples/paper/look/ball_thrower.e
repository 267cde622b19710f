note
	description: "Shows the ball one second after it is asked to (a stand-in for the world)."

class
	BALL_THROWER

create
	make

feature {NONE} -- Initialization

	make (a_ball: separate BALL_SIGNALER)
			-- Thrower of `a_ball'.
		do
			ball := a_ball
		end

feature -- Basic operations

	throw
			-- Wait a second, then show the ball 1 m ahead, 0.5 m to the left.
		do
			(create {TIMER}.make).sleep (1.0)
			show (ball)
		end

feature {NONE} -- Implementation

	ball: separate BALL_SIGNALER
			-- The ball.

	show (a_ball: separate BALL_SIGNALER)
			-- Show `a_ball'.
		do
			a_ball.show (1.0, 0.5)
		end

end
