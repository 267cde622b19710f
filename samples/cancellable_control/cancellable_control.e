note
	description: "[
		A cancellable control loop: a controller runs guarded by a stop signaler, and a
		supervisor on another processor cancels it after a number of steps.
	]"

class
	CANCELLABLE_CONTROL

create
	make

feature {NONE} -- Initialization

	make
			-- Start the controller and its supervisor, then report once the motor is at rest.
		local
			l_motor: separate MOTOR
			l_stop: separate STOP_SIGNALER
			l_controller: separate SPEED_CONTROLLER
			l_supervisor: separate SUPERVISOR
		do
			create l_motor.make
			create l_stop.make
			create l_controller.make (l_motor, l_stop)
			create l_supervisor.make (l_motor, l_stop, Step_limit)
			start_controller (l_controller)
			start_supervisor (l_supervisor)
			report (l_motor, l_stop)
		end

feature {NONE} -- Implementation

	start_controller (a_controller: separate SPEED_CONTROLLER)
			-- Let `a_controller' run until stopped.
		do
			a_controller.run
		end

	start_supervisor (a_supervisor: separate SUPERVISOR)
			-- Let `a_supervisor' watch the controller.
		do
			a_supervisor.supervise
		end

	report (a_motor: separate MOTOR; a_stop: separate STOP_SIGNALER)
			-- Once the loop has been cancelled and the motor brought to rest, say so.
		require
			cancelled: a_stop.is_stop_requested
			at_rest: a_motor.speed = 0
		do
			print ("Motor at rest after " + a_motor.command_count.out + " speed commands%N")
		ensure
			one_command_per_step_and_one_to_stop: a_motor.command_count = Step_limit + 1
		end

	Step_limit: INTEGER = 6
			-- Steps the control loop may make.

end
