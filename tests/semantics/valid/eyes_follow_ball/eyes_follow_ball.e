note
	description: "[
		A robot's eyes follow a ball: a simulated camera moves the ball signaler, a controller
		turns the eyes each time the ball has moved, and a stop signaler ends the run.
	]"

class
	EYES_FOLLOW_BALL

create
	make

feature {NONE} -- Initialization

	make
			-- Wire the signalers, the controller and the simulated camera, then run them.
		local
			l_ball: separate BALL_SIGNALER
			l_stop: separate STOP_SIGNALER
			l_eyes: separate EYES
			l_controller: separate EYES_CONTROLLER
			l_camera: separate BALL_CAMERA
		do
			create l_ball.make
			create l_stop.make
			create l_eyes.make
			create l_controller.make (l_ball, l_eyes, l_stop)
			create l_camera.make (l_ball, l_stop, Frame_count)
			start_controller (l_controller)
			start_camera (l_camera)
			report (l_eyes, l_stop)
		end

feature {NONE} -- Implementation

	start_controller (a_controller: separate EYES_CONTROLLER)
			-- Let `a_controller' follow the ball until stopped.
		do
			a_controller.run
		end

	start_camera (a_camera: separate BALL_CAMERA)
			-- Let `a_camera' film the ball.
		do
			a_camera.run
		end

	report (a_eyes: separate EYES; a_stop: separate STOP_SIGNALER)
			-- Print how often `a_eyes' moved, once `a_stop' has been raised.
		require
			stopped: a_stop.is_stop_requested
		do
			print ("The eyes moved " + a_eyes.move_count.out + " times%N")
		end

	Frame_count: INTEGER = 10
			-- Frames the camera films.

end
