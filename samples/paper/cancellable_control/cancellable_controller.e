note
	description: "[
		The paper's cancellable control loop: `start_cancellable_control' repeats `control' until the
		stop signaler says stop. Each `control' reserves the stop signaler and the sensors together,
		so no step runs once the stop is seen. The loop does not sleep between steps: in simulated
		time the runtime charges it a quantum every few separate calls (docs/RUNTIME.md). The robot
		is this controller's own (non-separate): `control' calls it without reserving it.
	]"

class
	CANCELLABLE_CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_stop: separate STOP_SIGNALER; a_namespace: separate STRING)
			-- Controller of the Thymio under `a_namespace', cancelled through `a_stop'.
		do
			stop_signaler := a_stop
			create robot.make (a_namespace)
			create some_signaler.make_thymio (a_namespace)
		end

feature -- Access

	stop_signaler: separate STOP_SIGNALER
			-- Says when to stop.

	some_signaler: separate SOME_SIGNALER
			-- What the robot senses.

	robot: THYMIO_ROBOT
			-- The robot, in this controller's region.

	step_count: INTEGER
			-- Steps of `control' that ran.

	stop_requested: BOOLEAN
			-- Has the loop seen the stop request?

feature -- Basic operations

	run
			-- The loop, then a stop of the robot.
		do
			start_cancellable_control
			robot.stop
			print ("Controller: stopped after " + step_count.out + " steps%N")
		end

feature -- The paper's listing

	start_cancellable_control
		do
			from
			until
				stop_requested
			loop
				control (stop_signaler, some_signaler)
			end
		end

	control (s_sig: separate STOP_SIGNALER; s: separate SOME_SIGNALER)
		do
			if s_sig.is_stop_requested then
				stop_requested := True
			else
				-- The paper's placeholder for the control step, filled in: drive on, turn away
				-- from what is in front.
				if s.has_obstacle then
					robot.turn_left
				else
					robot.apply_default_speed
				end
				step_count := step_count + 1
			end
		end

end
