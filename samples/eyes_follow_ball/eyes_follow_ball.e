note
	description: "[
		A robot's eyes follow a ball: a thrower moves the ball signaler, a controller turns
		the head each time the ball has moved.
	]"

class
	EYES_FOLLOW_BALL

create
	make

feature {NONE} -- Initialization

	make
			-- Wire the ball, the head, the controller and the thrower, run them, then report.
		local
			l_ball: separate BALL_SIGNALER
			l_head: separate HEAD
			l_controller: separate EYES_CONTROLLER
			l_thrower: separate BALL_THROWER
		do
			create l_ball.make
			create l_head.make
			create l_controller.make (l_ball, l_head)
			create l_thrower.make (l_ball, l_head)
			start_controller (l_controller)
			start_thrower (l_thrower)
			report (l_ball, l_head)
		end

feature {NONE} -- Implementation

	start_controller (a_controller: separate EYES_CONTROLLER)
			-- Let `a_controller' follow the ball until it is gone.
		do
			a_controller.run
		end

	start_thrower (a_thrower: separate BALL_THROWER)
			-- Let `a_thrower' play.
		do
			a_thrower.play
		end

	report (a_ball: separate BALL_SIGNALER; a_head: separate HEAD)
			-- Once the ball is gone, tell how the head moved.
		require
			game_over: a_ball.is_gone
		do
			print ("Head turned " + a_head.move_count.out + " times and looks at " + a_head.pan.out + " degrees%N")
		ensure
			followed_every_throw: a_head.move_count = a_ball.version
		end

end
