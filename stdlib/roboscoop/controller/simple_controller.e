note
	description: "[
		The paper's simple controller: go straight while the way is clear, turn away from an
		obstacle, stop on an emergency. Each behaviour is a guarded routine over separate
		RANGE_SIGNALER and STOP_SIGNALER arguments whose wait condition says when it applies
		(`go_straight', `turn', `stop_on_emergency'); it commands a separate DIFFERENTIAL_DRIVE.
		Several controllers can each call one of them repeatedly (the guard then blocks until
		it holds), or `run' serves all three on one processor at `period' nanoseconds per
		iteration until the stop signaler fires, then stops the robot.
	]"

class
	SIMPLE_CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_stop: separate STOP_SIGNALER; a_range: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE;
			a_linear, a_angular: REAL_64; a_period: INTEGER_64)
			-- Controller driving at `a_linear' m/s, turning at `a_angular' rad/s, every `a_period' ns.
		require
			positive_speeds: a_linear > 0.0 and a_angular > 0.0
			non_negative_period: a_period >= 0
		do
			stop_signaler := a_stop
			range_signaler := a_range
			drive := a_drive
			linear_speed := a_linear
			angular_speed := a_angular
			period := a_period
		end

feature -- Access

	stop_signaler: separate STOP_SIGNALER
			-- Emergency stop.

	range_signaler: separate RANGE_SIGNALER
			-- Obstacles.

	drive: separate DIFFERENTIAL_DRIVE
			-- Where commands go.

	linear_speed, angular_speed: REAL_64
			-- Forward speed and turn rate commanded.

	period: INTEGER_64
			-- Nanoseconds between iterations of `run'.

	iteration_count: INTEGER
			-- Iterations of `run'.

feature -- Status report

	is_finished: BOOLEAN
			-- Has `run' seen the stop request?

feature -- Basic operations

	go_straight (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Drive forward when nothing is in front.
		require
			not s_sig.is_stop_requested
			not r_sig.has_obstacle
		do
			a_drive.send (linear_speed, 0.0)
		end

	turn (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Turn in place away from an obstacle in front (to the right when it is on the left).
		require
			not s_sig.is_stop_requested
			r_sig.has_obstacle
		do
			if r_sig.is_obstacle_left then
				a_drive.send (0.0, - angular_speed)
			else
				a_drive.send (0.0, angular_speed)
			end
		end

	stop_on_emergency (s_sig: separate STOP_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Stop the robot once a stop is requested.
		require
			s_sig.is_stop_requested
		do
			a_drive.stop
		end

	run
			-- Go straight or turn every `period' until the stop signaler fires; then stop the robot.
		do
			from
				is_finished := False
			until
				is_finished
			loop
				control (stop_signaler, range_signaler, drive)
				if not is_finished and period > 0 then
					(create {EXECUTION_ENVIRONMENT}).sleep (period)
				end
			end
		ensure
			finished: is_finished
		end

feature {NONE} -- Implementation

	control (s_sig: separate STOP_SIGNALER; r_sig: separate RANGE_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- One iteration: the behaviour whose guard holds (all three reserved together).
		do
			if s_sig.is_stop_requested then
				stop_on_emergency (s_sig, a_drive)
				is_finished := True
			elseif r_sig.has_obstacle then
				turn (s_sig, r_sig, a_drive)
			else
				go_straight (s_sig, r_sig, a_drive)
			end
			iteration_count := iteration_count + 1
		end

end
