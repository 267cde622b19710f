note
	description: "[
		A cancellable control loop: at a fixed rate, ramps a motor up to cruising speed,
		until its stop signaler asks it to stop; it then brings the motor to rest.
	]"

class
	SPEED_CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_motor: separate MOTOR; a_stop: separate STOP_SIGNALER)
			-- Controller driving `a_motor' until `a_stop' is raised.
		do
			motor := a_motor
			stop := a_stop
		end

feature -- Access

	steps: INTEGER
			-- Control steps made so far.

feature -- Basic operations

	run
			-- Make control steps at a fixed rate until a stop is requested.
		do
			from
			until
				is_stopped
			loop
				control_step (motor, stop)
				if not is_stopped then
					(create {EXECUTION_ENVIRONMENT}).sleep (Period)
				end
			end
		end

feature {NONE} -- Implementation

	control_step (a_motor: separate MOTOR; a_stop: separate STOP_SIGNALER)
			-- Speed `a_motor' up towards cruising speed, or bring it to rest if a stop is requested.
		require
			running: not is_stopped
		do
			if a_stop.is_stop_requested then
				a_motor.set_speed (0)
				is_stopped := True
				print ("Controller: stop requested after " + steps.out + " steps, motor at rest%N")
			else
				a_motor.set_speed ((a_motor.speed + Acceleration).min (Cruising_speed))
				steps := steps + 1
				print ("Controller: step " + steps.out + ", speed " + a_motor.speed.out + "%N")
			end
		ensure
			stopped_on_request: is_stopped = a_stop.is_stop_requested
			at_rest_when_stopped: is_stopped implies a_motor.speed = 0
		end

	motor: separate MOTOR
	stop: separate STOP_SIGNALER
			-- The motor driven and the signaler that stops the loop.

	is_stopped: BOOLEAN
			-- Has the loop stopped?

	Acceleration: INTEGER = 20
			-- Speed gained per step.

	Cruising_speed: INTEGER = 80
			-- Speed kept once reached.

	Period: INTEGER_64 = 10_000_000
			-- Time between two control steps, in nanoseconds.

end
