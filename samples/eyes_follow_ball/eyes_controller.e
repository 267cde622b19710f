note
	description: "Turns the head towards the ball each time the ball signaler has a new position."

class
	EYES_CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_ball: separate BALL_SIGNALER; a_head: separate HEAD)
			-- Controller turning `a_head' towards `a_ball'.
		do
			ball := a_ball
			head := a_head
		end

feature -- Access

	seen_version: INTEGER
			-- Version of the ball signaler followed last.

feature -- Basic operations

	run
			-- Follow the ball until it is put away.
		do
			from
			until
				is_stopped
			loop
				eyes_follow_ball (ball, head)
			end
			print ("Eyes: the ball is gone after " + seen_version.out + " positions%N")
		end

feature {NONE} -- Implementation

	eyes_follow_ball (a_ball: separate BALL_SIGNALER; a_head: separate HEAD)
			-- As soon as the ball has moved, turn `a_head' towards it; stop once it is gone.
		require
			moved_or_gone: a_ball.version > seen_version or a_ball.is_gone
		do
			if a_ball.version > seen_version then
				seen_version := a_ball.version
				a_head.turn_to (a_head.pan_towards (a_ball.bearing))
				print ("Eyes: ball at " + a_ball.bearing.out + " degrees, head turns to " + a_head.pan.out + "%N")
			else
				is_stopped := True
			end
		ensure
			facing_ball: a_head.is_facing (a_ball.bearing)
			caught_up: seen_version = a_ball.version
		end

	ball: separate BALL_SIGNALER
			-- Where the ball is.

	head: separate HEAD
			-- The head to turn.

	is_stopped: BOOLEAN
			-- Has the ball gone?

end
