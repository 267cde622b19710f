note
	description: "Watches the motor and cancels the control loop once it has made a given number of steps."

class
	SUPERVISOR

create
	make

feature {NONE} -- Initialization

	make (a_motor: separate MOTOR; a_stop: separate STOP_SIGNALER; a_limit: INTEGER)
			-- Supervisor raising `a_stop' once `a_motor' has had `a_limit' speed commands.
		require
			positive_limit: a_limit > 0
		do
			motor := a_motor
			stop := a_stop
			step_limit := a_limit
		end

feature -- Access

	step_limit: INTEGER
			-- Control steps allowed.

feature -- Basic operations

	supervise
			-- Cancel the control loop after `step_limit' steps.
		do
			stop_after_limit (motor, stop)
		end

feature {NONE} -- Implementation

	stop_after_limit (a_motor: separate MOTOR; a_stop: separate STOP_SIGNALER)
			-- Once `a_motor' has had `step_limit' commands, request a stop.
		require
			limit_reached: a_motor.command_count >= step_limit
		do
			a_stop.request_stop
			print ("Supervisor: " + a_motor.command_count.out + " steps done, stop requested%N")
		ensure
			requested: a_stop.is_stop_requested
		end

	motor: separate MOTOR
	stop: separate STOP_SIGNALER
			-- The motor watched and the signaler raised.

end
