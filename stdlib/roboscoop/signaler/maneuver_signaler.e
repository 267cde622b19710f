note
	description: "[
		The state of a timed maneuver shared by the controllers of a behaviour: while one is
		active (`is_active'), the controller that started it drives it and the others hold back
		(their guards say `not m.is_active'). A maneuver is one or two phases, each a velocity
		(linear, angular) held until a time on the runtime's clock: for instance back off, then
		turn. The controller in charge calls `advance' with the current time to move to the
		next phase and `finish' to end it.
	]"

class
	MANEUVER_SIGNALER

create
	make

feature {NONE} -- Initialization

	make
			-- No maneuver.
		do
		ensure
			idle: not is_active
		end

feature -- Access

	linear, angular: REAL_64
			-- Velocity of the current phase (m/s, rad/s).

	ends_at: REAL_64
			-- Clock time (s) at which the current phase ends.

	next_linear, next_angular, next_duration: REAL_64
			-- The phase after the current one (duration 0: none).

	started_count: INTEGER
			-- Maneuvers started so far.

feature -- Status report

	is_active: BOOLEAN
			-- Is a maneuver under way?

	has_next_phase: BOOLEAN
			-- Does a phase follow the current one?
		do
			Result := next_duration > 0.0
		end

	is_phase_over (a_now: REAL_64): BOOLEAN
			-- Is the current phase over at time `a_now'?
		do
			Result := a_now >= ends_at
		end

feature -- Basic operations

	start (a_linear, a_angular, a_now, a_duration: REAL_64)
			-- Start a one-phase maneuver at time `a_now' for `a_duration' seconds.
		require
			non_negative_duration: a_duration >= 0.0
		do
			start_two (a_linear, a_angular, a_now, a_duration, 0.0, 0.0, 0.0)
		ensure
			active: is_active
			no_next: not has_next_phase
		end

	start_two (a_linear, a_angular, a_now, a_duration, a_next_linear, a_next_angular, a_next_duration: REAL_64)
			-- Start a maneuver: (`a_linear', `a_angular') for `a_duration' s from `a_now', then
			-- (`a_next_linear', `a_next_angular') for `a_next_duration' s.
		require
			non_negative_durations: a_duration >= 0.0 and a_next_duration >= 0.0
		do
			linear := a_linear
			angular := a_angular
			ends_at := a_now + a_duration
			next_linear := a_next_linear
			next_angular := a_next_angular
			next_duration := a_next_duration
			is_active := True
			started_count := started_count + 1
		ensure
			active: is_active
			counted: started_count = old started_count + 1
		end

	advance (a_now: REAL_64)
			-- At time `a_now', with the current phase over: go to the next phase, or finish.
		require
			active: is_active
		do
			if has_next_phase then
				linear := next_linear
				angular := next_angular
				ends_at := a_now + next_duration
				next_duration := 0.0
			else
				finish
			end
		end

	extend (a_now, a_duration: REAL_64)
			-- Hold the current phase until `a_now' + `a_duration'.
		require
			active: is_active
			non_negative_duration: a_duration >= 0.0
		do
			ends_at := a_now + a_duration
		end

	finish
			-- End the maneuver.
		do
			is_active := False
			next_duration := 0.0
			linear := 0.0
			angular := 0.0
		ensure
			idle: not is_active
		end

end
