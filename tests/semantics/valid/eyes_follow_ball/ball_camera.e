note
	description: "Stand-in for a camera: moves the ball from side to side, then requests a stop."

class
	BALL_CAMERA

create
	make

feature {NONE} -- Initialization

	make (a_ball: separate BALL_SIGNALER; a_stop: separate STOP_SIGNALER; a_frames: INTEGER)
			-- Camera updating `a_ball' for `a_frames' frames, then raising `a_stop'.
		do
			ball := a_ball
			stop := a_stop
			frame_count := a_frames
		end

feature -- Access

	frame_count: INTEGER
			-- Frames to film.

feature -- Basic operations

	run
			-- Film every frame, then request a stop.
		local
			i: INTEGER
			l_environment: EXECUTION_ENVIRONMENT
		do
			create l_environment
			from
				i := 1
			until
				i > frame_count
			loop
				see_ball (ball, i)
				l_environment.sleep (Frame_period)
				i := i + 1
			end
			finish (stop)
		end

feature {NONE} -- Implementation

	see_ball (a_ball: separate BALL_SIGNALER; a_frame: INTEGER)
			-- Update `a_ball' with where it is at `a_frame'.
		do
			a_ball.update ((a_frame \\ 5 - 2).to_real_64 * 0.25, 1.0 + a_frame.to_real_64 * 0.1)
		end

	finish (a_stop: separate STOP_SIGNALER)
			-- Raise `a_stop'.
		do
			a_stop.request_stop
		end

	ball: separate BALL_SIGNALER
	stop: separate STOP_SIGNALER
			-- The signalers used.

	Frame_period: INTEGER_64 = 20_000_000
			-- Time between two frames, in nanoseconds.

end
