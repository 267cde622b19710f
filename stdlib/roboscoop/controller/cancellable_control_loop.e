note
	description: "[
		Repeats a step until its STOP_SIGNALER fires. The step is an agent (`make_with_action')
		or the routine `step' redefined in a descendant; it runs only when `is_ready' holds.
		Each iteration reserves the stop signaler, so a step never runs once the stop is seen.
		Not a busy loop: between iterations the loop sleeps `period' nanoseconds on the
		runtime's clock (virtual with --virtual-clock), so a guard that stays true runs at
		1 / `period' Hz. A step with a wait condition of its own (a guarded routine over
		separate arguments) waits for it instead.
	]"

class
	CANCELLABLE_CONTROL_LOOP

create
	make, make_with_action

feature {NONE} -- Initialization

	make (a_stop: separate STOP_SIGNALER; a_period: INTEGER_64)
			-- Loop stopped by `a_stop', one iteration every `a_period' nanoseconds.
		require
			non_negative_period: a_period >= 0
		do
			stop_signaler := a_stop
			period := a_period
		ensure
			stop_signaler_set: stop_signaler = a_stop
			period_set: period = a_period
			not_finished: not is_finished
		end

	make_with_action (a_stop: separate STOP_SIGNALER; a_period: INTEGER_64; a_action: PROCEDURE)
			-- Like `make', each iteration calling `a_action'.
		require
			non_negative_period: a_period >= 0
		do
			make (a_stop, a_period)
			action := a_action
		ensure
			action_set: action = a_action
		end

feature -- Access

	stop_signaler: separate STOP_SIGNALER
			-- Fires the end of the loop.

	period: INTEGER_64
			-- Nanoseconds slept between iterations.

	action: detachable PROCEDURE
			-- Called by `step' when attached.

	iteration_count: INTEGER
			-- Steps run.

feature -- Status report

	is_finished: BOOLEAN
			-- Has the loop seen the stop request?

	is_ready: BOOLEAN
			-- May the step run now? (Redefine to guard it; when False the iteration is skipped.)
		do
			Result := True
		end

feature -- Element change

	set_period (a_period: INTEGER_64)
			-- Set `period'.
		require
			non_negative_period: a_period >= 0
		do
			period := a_period
		ensure
			period_set: period = a_period
		end

feature -- Basic operations

	run
			-- Iterate until the stop signaler fires.
		do
			from
				is_finished := False
			until
				is_finished
			loop
				iterate (stop_signaler)
				if not is_finished then
					pause
				end
			end
		ensure
			finished: is_finished
		end

	step
			-- One iteration's work: call `action' (redefine for another step).
		do
			if attached action as a then
				a.call (Void)
			end
		end

feature {NONE} -- Implementation

	iterate (a_stop: separate STOP_SIGNALER)
			-- Run `step' unless `a_stop' has fired (checked while `a_stop' is reserved).
		do
			if a_stop.is_stop_requested then
				is_finished := True
			elseif is_ready then
				step
				iteration_count := iteration_count + 1
			end
		end

	pause
			-- Sleep `period' nanoseconds on the runtime's clock.
		do
			if period > 0 then
				(create {EXECUTION_ENVIRONMENT}).sleep (period)
			end
		end

end
