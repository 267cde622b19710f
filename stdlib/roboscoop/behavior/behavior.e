note
	description: "[
		A robot behaviour: it creates its controllers and launches them (`start'), and stops them
		through its STOP_SIGNALER (`stop'): every controller's guards read the signaler, so a stop
		request ends each loop at its next iteration or wakes it from its wait condition.
		`start' again after `stop' makes a fresh stop signaler and fresh controllers. A parent
		signaler given with `set_parent' also stops the behaviour (stop trees).
	]"

deferred class
	BEHAVIOR

feature -- Access

	stop_signaler: detachable separate STOP_SIGNALER
			-- Stops the controllers of the current run (Void before the first `start').

	parent: detachable separate STOP_SIGNALER
			-- Another signaler whose stop also stops this behaviour.

	start_count: INTEGER
			-- Times started.

feature -- Status report

	is_running: BOOLEAN
			-- Started and not stopped since?

feature -- Element change

	set_parent (a_parent: separate STOP_SIGNALER)
			-- Let a stop of `a_parent' stop this behaviour too (from the next `start').
		do
			parent := a_parent
		ensure
			parent_set: parent = a_parent
		end

feature -- Basic operations

	start
			-- Create and launch the controllers, with a fresh stop signaler.
		require
			not_running: not is_running
		local
			s: separate STOP_SIGNALER
		do
			create s.make
			stop_signaler := s
			if attached parent as p then
				adopt (p, s)
			end
			launch (s)
			is_running := True
			start_count := start_count + 1
		ensure
			running: is_running
			counted: start_count = old start_count + 1
		end

	stop
			-- Ask every controller to stop (the robot is stopped by the behaviour's emergency path).
		do
			if attached stop_signaler as s then
				request_stop (s)
			end
			is_running := False
		ensure
			stopped: not is_running
		end

feature {NONE} -- Implementation

	launch (a_stop: separate STOP_SIGNALER)
			-- Create the controllers, guarded by `a_stop', and set them going (asynchronously).
		deferred
		end

	request_stop (a_stop: separate STOP_SIGNALER)
			-- Raise `a_stop'.
		do
			a_stop.request_stop
		end

	adopt (a_parent, a_child: separate STOP_SIGNALER)
			-- Make `a_child' stop with `a_parent'.
		do
			a_parent.add_child (a_child)
		end

end
