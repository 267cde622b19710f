note
	description: "[
		Offers one ROS 2 action (rcl_action's services and topics, in rmw_cyclonedds_cpp's format,
		docs/ROBOTS.md). Each goal request arrives as a call on the server's processor: `accepts'
		decides (every goal by default; redefine it to refuse some), and an accepted goal becomes
		`last_goal', a ROS_SERVER_GOAL in this server's region, which the program works on: it
		publishes feedback and ends the goal with a result. A cancel request of a goal arrives the
		same way: `accepts_cancel' decides (yes by default), and the goal's `is_cancel_requested'
		becomes true. `goal_count' and the goals' state can be used in wait conditions. Goal,
		feedback and result classes come from `scoopc msg pkg/action/Name'. Needs a ROS 2 robot
		over DDS (`scoopc run --robot ros2').
	]"

class
	ROS_ACTION_SERVER [GOAL -> ROS_MESSAGE, FEEDBACK -> ROS_MESSAGE, ACTION_RESULT -> ROS_MESSAGE]

create
	make

feature {NONE} -- Initialization

	make (a_action, a_type: separate STRING)
			-- Serve `a_action' (a full name: "/fibonacci") of type `a_type'
			-- ("example_interfaces/action/Fibonacci").
		do
			create action.make_from_separate (a_action)
			create action_type.make_from_separate (a_type)
			start_serving
		end

feature -- Access

	action: STRING
			-- Full name of the action.

	action_type: STRING
			-- Its ROS 2 type.

	goal_count: INTEGER
			-- Goals accepted so far.

	last_goal: detachable ROS_SERVER_GOAL [GOAL, FEEDBACK, ACTION_RESULT]
			-- The goal accepted last.

	cancel_count: INTEGER
			-- Cancel requests accepted so far.

feature -- Status report

	accepts (a_goal: GOAL): BOOLEAN
			-- Is `a_goal' accepted? (Every goal; redefine to refuse some.)
		do
			Result := True
		end

	accepts_cancel (a_goal: ROS_SERVER_GOAL [GOAL, FEEDBACK, ACTION_RESULT]): BOOLEAN
			-- Is a request to cancel `a_goal' accepted? (Yes; redefine to refuse some.)
		do
			Result := True
		end

feature -- Basic operations

	close
			-- Stop serving.
		external
			"Python"
		end

feature {NONE} -- Transport

	on_goal (a_goal: GOAL; a_id: STRING): detachable ROS_SERVER_GOAL [GOAL, FEEDBACK, ACTION_RESULT]
			-- Called on this processor for each goal request: the new goal if accepted.
		local
			l_goal: ROS_SERVER_GOAL [GOAL, FEEDBACK, ACTION_RESULT]
		do
			if accepts (a_goal) then
				create l_goal.make (a_goal, a_id)
				last_goal := l_goal
				goal_count := goal_count + 1
				Result := l_goal
			end
		end

	on_cancel (a_goal: ROS_SERVER_GOAL [GOAL, FEEDBACK, ACTION_RESULT]): BOOLEAN
			-- Called on this processor for each request to cancel `a_goal': accepted?
		do
			Result := accepts_cancel (a_goal)
			if Result then
				a_goal.mark_cancel_requested
				cancel_count := cancel_count + 1
			end
		end

	start_serving
			-- Offer the action on the transport.
		external
			"Python"
		end

end
