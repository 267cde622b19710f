note
	description: "[
		Sends goals to one ROS 2 action (rcl_action's services and topics, in rmw_cyclonedds_cpp's
		format, docs/ROBOTS.md). `send_goal' waits for the server's answer and returns the goal's
		handle, a separate object of its own: its status, latest feedback and result can be used in
		wait conditions, and it can be cancelled. Goal, feedback and result classes come from
		`scoopc msg pkg/action/Name'. Needs a ROS 2 robot over DDS (`scoopc run --robot ros2').
	]"

class
	ROS_ACTION_CLIENT [GOAL -> ROS_MESSAGE, FEEDBACK -> ROS_MESSAGE, ACTION_RESULT -> ROS_MESSAGE]

create
	make

feature {NONE} -- Initialization

	make (a_action, a_type: separate STRING)
			-- Client of the action `a_action' (a full name: "/navigate_to_pose") of type `a_type'
			-- ("nav2_msgs/action/NavigateToPose").
		do
			create action.make_from_separate (a_action)
			create action_type.make_from_separate (a_type)
			timeout := 10.0
		ensure
			default_timeout: timeout = 10.0
		end

feature -- Access

	action: STRING
			-- Full name of the action.

	action_type: STRING
			-- Its ROS 2 type ("nav2_msgs/action/NavigateToPose").

	timeout: REAL_64
			-- Seconds `send_goal' waits for the server's answer.

	goal_count: INTEGER
			-- Goals sent so far.

feature -- Element change

	set_timeout (a_seconds: REAL_64)
			-- Wait at most `a_seconds' for the server's answer to a goal.
		require
			positive: a_seconds > 0.0
		do
			timeout := a_seconds
		ensure
			set: timeout = a_seconds
		end

feature -- Basic operations

	is_available (a_seconds: REAL_64): BOOLEAN
			-- Is a server of `action' there (waiting up to `a_seconds' for one)? Never without a
			-- ROS 2 robot over DDS.
		external
			"Python"
		end

	send_goal (a_goal: separate GOAL): separate ROS_GOAL_HANDLE [FEEDBACK, ACTION_RESULT]
			-- Send `a_goal'; its handle once the server answered (accepted or not). No answer within
			-- `timeout' raises an exception.
		local
			l_handle: separate ROS_GOAL_HANDLE [FEEDBACK, ACTION_RESULT]
		do
			create l_handle.make (action)
			start_goal (a_goal, l_handle)
			goal_count := goal_count + 1
			Result := l_handle
		ensure
			counted: goal_count = old goal_count + 1
		end

feature {NONE} -- Transport

	start_goal (a_goal: separate GOAL; a_handle: separate ROS_GOAL_HANDLE [FEEDBACK, ACTION_RESULT])
			-- Send `a_goal', tell `a_handle' the answer.
		do
			a_handle.set_accepted (send (a_goal, a_handle))
		end

	send (a_goal: separate ROS_MESSAGE; a_handle: separate ROS_GOAL_HANDLE [FEEDBACK, ACTION_RESULT]): BOOLEAN
			-- Send `a_goal' and wait for the answer: accepted? Its status, feedback and result go to
			-- `a_handle' from then on.
		external
			"Python"
		end

end
