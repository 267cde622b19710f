note
	description: "[
		The paper's cancellable control loop as a program: a CANCELLABLE_CONTROLLER drives the
		Thymio until, ten seconds later, the root asks it to stop with the paper's
		`set_stop_requested (True)'.
	]"

class
	CANCELLABLE_CONTROL

create
	make

feature {NONE} -- Initialization

	make
			-- Drive for ten seconds, then cancel.
		local
			env: ROBOT_ENVIRONMENT
			stop: separate STOP_SIGNALER
			controller: separate CANCELLABLE_CONTROLLER
			clock: TIMER
		do
			create env
			create stop.make
			create controller.make (stop, env.namespace)
			launch (controller)
			create clock.make
			clock.start
			clock.sleep (10.0)
			cancel (stop)
			print ("Root: stop requested after " + clock.elapsed.rounded.out + " s%N")
		end

feature {NONE} -- Frame

	launch (a_controller: separate CANCELLABLE_CONTROLLER)
			-- Set `a_controller' going.
		do
			a_controller.run
		end

	cancel (s_sig: separate STOP_SIGNALER)
			-- Ask the controller to stop (the paper's call).
		do
			s_sig.set_stop_requested (True)
		end

end
