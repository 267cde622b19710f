note
	description: "[
		The progress of a navigation behaviour, shared between its controller (which reports) and
		its clients (which read it or wait on it: `require nav.is_finished'): the mode, the
		outcome (`is_goal_reached', `is_unreachable', `is_stopped') and a few figures.
	]"

class
	NAVIGATION_SIGNALER

create
	make

feature {NONE} -- Initialization

	make
			-- Not started.
		do
			mode := Idle
		ensure
			idle: mode = Idle and not is_finished
		end

feature -- Access

	mode: INTEGER
			-- One of `Idle', `Motion_to_goal', `Boundary_following', `Goal_reached', `Goal_unreachable', `Stopped'.

	Idle: INTEGER = 1
	Motion_to_goal: INTEGER = 2
	Boundary_following: INTEGER = 3
	Goal_reached: INTEGER = 4
	Goal_unreachable: INTEGER = 5
	Stopped: INTEGER = 6
			-- Modes.

	mode_name: STRING
			-- `mode' in words.
		do
			inspect mode
			when Motion_to_goal then
				Result := "motion to goal"
			when Boundary_following then
				Result := "boundary following"
			when Goal_reached then
				Result := "goal reached"
			when Goal_unreachable then
				Result := "goal unreachable"
			when Stopped then
				Result := "stopped"
			else
				Result := "idle"
			end
		end

	distance_to_goal: REAL_64
			-- Distance from the robot to the goal at the last report (m).

	path_length: REAL_64
			-- Distance travelled so far (m).

	boundary_count: INTEGER
			-- Times boundary following began.

	leave_count: INTEGER
			-- Times boundary following ended by the leave condition.

	report_count: INTEGER
			-- Reports received.

feature -- Status report

	is_goal_reached: BOOLEAN
			-- Has the robot reached the goal?
		do
			Result := mode = Goal_reached
		end

	is_unreachable: BOOLEAN
			-- Has the behaviour found the goal unreachable?
		do
			Result := mode = Goal_unreachable
		end

	is_stopped: BOOLEAN
			-- Was the behaviour stopped before an outcome?
		do
			Result := mode = Stopped
		end

	is_finished: BOOLEAN
			-- Is the navigation over (reached, unreachable or stopped)?
		do
			Result := mode = Goal_reached or mode = Goal_unreachable or mode = Stopped
		end

feature -- Element change

	report (a_mode: INTEGER; a_distance, a_path_length: REAL_64)
			-- The controller is in `a_mode', `a_distance' from the goal, having travelled `a_path_length'.
		require
			valid_mode: Idle <= a_mode and a_mode <= Stopped
			not_finished: not is_finished
		do
			if a_mode = Boundary_following and mode /= Boundary_following then
				boundary_count := boundary_count + 1
			elseif mode = Boundary_following and a_mode = Motion_to_goal then
				leave_count := leave_count + 1
			end
			mode := a_mode
			distance_to_goal := a_distance
			path_length := a_path_length
			report_count := report_count + 1
		ensure
			mode_set: mode = a_mode
		end

	reset
			-- Back to `Idle' for a new run.
		do
			mode := Idle
			boundary_count := 0
			leave_count := 0
			report_count := 0
			path_length := 0.0
		ensure
			idle: mode = Idle
		end

end
