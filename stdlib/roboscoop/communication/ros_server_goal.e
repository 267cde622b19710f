note
	description: "[
		A goal accepted by a ROS_ACTION_SERVER, in the server's region: the goal message, its id,
		whether a cancel was requested; `publish_feedback' while it runs, then one of `succeed',
		`abort' or `cancel_done' (after a cancel request) ends it with a result, which the client's
		result request gets.
	]"

class
	ROS_SERVER_GOAL [GOAL -> ROS_MESSAGE, FEEDBACK -> ROS_MESSAGE, ACTION_RESULT -> ROS_MESSAGE]

create
	make

feature {NONE} -- Initialization

	make (a_goal: GOAL; a_id: STRING)
			-- The goal `a_goal' with the id `a_id' (its UUID in hexadecimal).
		do
			goal := a_goal
			id := a_id
		end

feature -- Access

	goal: GOAL
			-- What the client asked.

	id: STRING
			-- The goal's UUID, in hexadecimal.

	feedback_count: INTEGER
			-- Feedback messages published.

	final_status: INTEGER
			-- How it ended (action_msgs/msg/GoalStatus: 4 succeeded, 5 canceled, 6 aborted), 0 while
			-- it runs.

feature -- Status report

	is_cancel_requested: BOOLEAN
			-- Did a client ask to cancel it (and the server accept)?

	is_ended: BOOLEAN
			-- Has it ended?
		do
			Result := final_status /= 0
		end

feature -- Basic operations

	publish_feedback (a_feedback: separate FEEDBACK)
			-- Tell the clients how the goal is going.
		require
			running: not is_ended
		do
			send_feedback (a_feedback)
			feedback_count := feedback_count + 1
		end

	succeed (a_result: separate ACTION_RESULT)
			-- End the goal: reached, with `a_result'.
		require
			running: not is_ended
		do
			finish (a_result, 4)
			final_status := 4
		ensure
			ended: is_ended
		end

	abort (a_result: separate ACTION_RESULT)
			-- End the goal: given up, with `a_result'.
		require
			running: not is_ended
		do
			finish (a_result, 6)
			final_status := 6
		ensure
			ended: is_ended
		end

	cancel_done (a_result: separate ACTION_RESULT)
			-- End the goal as cancelled, with `a_result'.
		require
			running: not is_ended
			asked: is_cancel_requested
		do
			finish (a_result, 5)
			final_status := 5
		ensure
			ended: is_ended
		end

feature -- Transport

	mark_cancel_requested
			-- A cancel request was accepted (told by the server).
		do
			is_cancel_requested := True
		ensure
			requested: is_cancel_requested
		end

feature {NONE} -- Transport

	send_feedback (a_feedback: separate ROS_MESSAGE)
			-- Publish `a_feedback' on the action's feedback topic.
		external
			"Python"
		end

	finish (a_result: separate ROS_MESSAGE; a_status: INTEGER)
			-- End the goal with `a_status' and `a_result'.
		external
			"Python"
		end

end
