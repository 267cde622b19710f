note
	description: "[
		The paper's `look' as a program: two eyes turn toward the ball once it is visible. `look' is
		the paper's routine (a wait condition on the ball, both eyes reserved with it); the rest is
		its frame: the eyes, the ball's signaler and a thrower that shows the ball after a second.
	]"

class
	LOOK

create
	make

feature {NONE} -- Initialization

	make
			-- Throw the ball, look at it, say where the eyes look.
		local
			left_eye, right_eye: separate EYE
			ball: separate BALL_SIGNALER
			thrower: separate BALL_THROWER
		do
			create left_eye.make ("Left", -0.03)
			create right_eye.make ("Right", 0.03)
			create ball.make
			create thrower.make (ball)
			throw (thrower)
			look (left_eye, right_eye, ball)
			report (left_eye, right_eye)
		end

feature -- The paper's listing

	look (left_eye, right_eye: separate EYE; ball: separate BALL_SIGNALER)
		require
			ball.is_visible
		do
			left_eye.look_at (ball.x, ball.y)
			right_eye.look_at (ball.x, ball.y)
		end

feature {NONE} -- Frame

	throw (a_thrower: separate BALL_THROWER)
			-- Let `a_thrower' show the ball in a while.
		do
			a_thrower.throw
		end

	report (a_left, a_right: separate EYE)
			-- Say how often each eye moved.
		do
			print ("Eyes moved: left " + a_left.move_count.out + ", right " + a_right.move_count.out + "%N")
		end

end
