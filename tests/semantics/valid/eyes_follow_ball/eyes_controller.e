note
	description: "Turns the eyes towards the ball each time the ball signaler has a new position."

class
	EYES_CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_ball: separate BALL_SIGNALER; a_eyes: separate EYES; a_stop: separate STOP_SIGNALER)
			-- Controller turning `a_eyes' towards `a_ball' until `a_stop' is raised.
		do
			ball := a_ball
			eyes := a_eyes
			stop := a_stop
		end

feature -- Access

	seen_version: INTEGER
			-- Version of the ball signaler handled last.

feature -- Basic operations

	run
			-- Follow the ball until a stop is requested.
		do
			from
			until
				is_stopped
			loop
				follow (ball, eyes, stop)
			end
		end

feature {NONE} -- Implementation

	follow (a_ball: separate BALL_SIGNALER; a_eyes: separate EYES; a_stop: separate STOP_SIGNALER)
			-- Once the ball has moved or a stop is requested, turn `a_eyes' towards `a_ball' or stop.
		require
			moved_or_stopped: a_ball.version > seen_version or a_stop.is_stop_requested
		do
			if a_stop.is_stop_requested then
				is_stopped := True
			else
				seen_version := a_ball.version
				a_eyes.look_at (clipped (a_ball.x / a_ball.y, a_eyes.Max_pan))
			end
		end

	clipped (a_value, a_limit: REAL_64): REAL_64
			-- `a_value' brought within [-`a_limit', `a_limit'].
		require
			positive_limit: a_limit > 0.0
		do
			if a_value > a_limit then
				Result := a_limit
			elseif a_value < -a_limit then
				Result := -a_limit
			else
				Result := a_value
			end
		ensure
			within: -a_limit <= Result and Result <= a_limit
		end

	is_stopped: BOOLEAN
			-- Has the controller stopped?

	ball: separate BALL_SIGNALER
	eyes: separate EYES
	stop: separate STOP_SIGNALER
			-- The signalers and the actuator used.

end
