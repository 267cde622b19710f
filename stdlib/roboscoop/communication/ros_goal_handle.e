note
	description: "[
		One goal sent by a ROS_ACTION_CLIENT, on a processor of its own. The transport tells it the
		goal's status (action_msgs/msg/GoalStatus), each feedback and the result as asynchronous
		calls on its processor (logged by an outside client, as subscriptions deliver messages), so
		`status', `feedback' and `has_result' can be used in wait conditions. `cancel' asks the
		server to cancel the goal.
	]"

class
	ROS_GOAL_HANDLE [FEEDBACK -> ROS_MESSAGE, ACTION_RESULT -> ROS_MESSAGE]

create
	make

feature {NONE} -- Initialization

	make (a_action: separate STRING)
			-- Handle of a goal of the action `a_action'.
		do
			create action.make_from_separate (a_action)
		end

feature -- Access

	action: STRING
			-- Full name of the goal's action.

	status: INTEGER
			-- The goal's latest status (`Status_unknown' .. `Status_aborted'), from the server's
			-- status topic, then from its result.

	feedback: detachable FEEDBACK
			-- The latest feedback, if any came.

	feedback_count: INTEGER
			-- Feedback messages delivered (the transport keeps only the newest undelivered one).

	goal_result: detachable ACTION_RESULT
			-- The result, once it came.

	cancel_code: INTEGER
			-- The server's answer to `cancel' (action_msgs/srv/CancelGoal: 0 accepted, 1 rejected,
			-- 2 unknown goal, 3 already ended), -1 while none came.

feature -- Status report

	is_answered: BOOLEAN
			-- Did the server answer the goal request?

	is_accepted: BOOLEAN
			-- Did it accept the goal?

	is_rejected: BOOLEAN
			-- Did it refuse the goal?
		do
			Result := is_answered and not is_accepted
		end

	has_result: BOOLEAN
			-- Did the result come?

	is_done: BOOLEAN
			-- Is the goal over: rejected, or its result came?
		do
			Result := is_rejected or has_result
		end

	is_succeeded: BOOLEAN
			-- Did the goal succeed?
		do
			Result := has_result and status = Status_succeeded
		end

	is_canceled: BOOLEAN
			-- Was it cancelled?
		do
			Result := has_result and status = Status_canceled
		end

	is_aborted: BOOLEAN
			-- Did the server abort it?
		do
			Result := has_result and status = Status_aborted
		end

	is_cancel_requested: BOOLEAN
			-- Was `cancel' called?

feature -- Constants (action_msgs/msg/GoalStatus)

	Status_unknown: INTEGER = 0
	Status_accepted: INTEGER = 1
	Status_executing: INTEGER = 2
	Status_canceling: INTEGER = 3
	Status_succeeded: INTEGER = 4
	Status_canceled: INTEGER = 5
	Status_aborted: INTEGER = 6

feature -- Basic operations

	cancel
			-- Ask the server to cancel the goal (once; the answer comes in `cancel_code').
		require
			accepted: is_accepted
		do
			if not is_cancel_requested then
				is_cancel_requested := True
				cancel_code := -1
				request_cancel
			end
		ensure
			requested: is_cancel_requested
		end

feature -- Transport

	set_accepted (a_accepted: BOOLEAN)
			-- The server's answer to the goal request (told by the client).
		do
			is_answered := True
			is_accepted := a_accepted
			if a_accepted and status = Status_unknown then
				status := Status_accepted
			end
		ensure
			answered: is_answered
			set: is_accepted = a_accepted
		end

feature {NONE} -- Transport

	on_status (a_status: INTEGER)
			-- A status from the server's status topic.
		do
			if not has_result then
				status := a_status
			end
		end

	on_feedback (a_feedback: FEEDBACK)
			-- The newest feedback.
		do
			feedback := a_feedback
			feedback_count := feedback_count + 1
		end

	on_result (a_status: INTEGER; a_result: ACTION_RESULT)
			-- The result, with the goal's final status.
		do
			status := a_status
			goal_result := a_result
			has_result := True
		end

	on_cancel_reply (a_code: INTEGER)
			-- The server's answer to the cancel request.
		do
			cancel_code := a_code
		end

	request_cancel
			-- Send the cancel request.
		external
			"Python"
		end

end
