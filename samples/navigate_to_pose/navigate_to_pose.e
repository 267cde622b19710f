note
	description: "[
		Sends a Nav2 NavigateToPose goal (x y on the command line, default 2.0 1.0, in the map
		frame) to /navigate_to_pose, waits on its result in a precondition, and cancels it when a
		STOP_SIGNALER fires: a DEADLINE fires it after the seconds given as third argument
		(default 60). Run against a ROS 2 robot with Nav2 (rmw_cyclonedds_cpp):
		  scoopc run samples/navigate_to_pose --robot ros2 -- 2.0 1.0 30
	]"

class
	NAVIGATE_TO_POSE

create
	make

feature {NONE} -- Initialization

	make
			-- Send the goal, follow it until its result or the deadline.
		local
			args: ARGUMENTS_32
			x, y, seconds: REAL_64
			client: separate ROS_ACTION_CLIENT [NAV2_MSGS_NAVIGATE_TO_POSE_GOAL, NAV2_MSGS_NAVIGATE_TO_POSE_FEEDBACK, NAV2_MSGS_NAVIGATE_TO_POSE_RESULT]
			goal: separate ROS_GOAL_HANDLE [NAV2_MSGS_NAVIGATE_TO_POSE_FEEDBACK, NAV2_MSGS_NAVIGATE_TO_POSE_RESULT]
			stop: separate STOP_SIGNALER
			deadline: separate DEADLINE
		do
			create args
			x := 2.0
			y := 1.0
			seconds := 60.0
			if args.argument_count >= 2 and then args.argument (1).is_double and then args.argument (2).is_double then
				x := args.argument (1).to_double
				y := args.argument (2).to_double
			end
			if args.argument_count >= 3 and then args.argument (3).is_double then
				seconds := args.argument (3).to_double
			end
			create client.make ("/navigate_to_pose", "nav2_msgs/action/NavigateToPose")
			if available (client) then
				goal := send (client, x, y)
				if is_accepted (goal) then
					create stop.make
					create deadline.make (stop, seconds)
					arm (deadline)
					follow (goal, stop)
					report (goal)
					disarm (deadline)
				else
					print ("the goal was rejected%N")
				end
			else
				print ("no action server /navigate_to_pose%N")
			end
		end

feature {NONE} -- Implementation

	available (a_client: separate ROS_ACTION_CLIENT [NAV2_MSGS_NAVIGATE_TO_POSE_GOAL, NAV2_MSGS_NAVIGATE_TO_POSE_FEEDBACK, NAV2_MSGS_NAVIGATE_TO_POSE_RESULT]): BOOLEAN
			-- Is Nav2's server there (within 30 s)?
		do
			Result := a_client.is_available (30.0)
		end

	send (a_client: separate ROS_ACTION_CLIENT [NAV2_MSGS_NAVIGATE_TO_POSE_GOAL, NAV2_MSGS_NAVIGATE_TO_POSE_FEEDBACK, NAV2_MSGS_NAVIGATE_TO_POSE_RESULT];
			a_x, a_y: REAL_64): separate ROS_GOAL_HANDLE [NAV2_MSGS_NAVIGATE_TO_POSE_FEEDBACK, NAV2_MSGS_NAVIGATE_TO_POSE_RESULT]
			-- Send the goal pose (`a_x', `a_y') in the map frame; its handle.
		local
			l_goal: NAV2_MSGS_NAVIGATE_TO_POSE_GOAL
		do
			create l_goal.make
			l_goal.pose.header.set_frame_id ("map")
			l_goal.pose.pose.position.set_x (a_x)
			l_goal.pose.pose.position.set_y (a_y)
			l_goal.pose.pose.orientation.set_w (1.0)
			print ("goal sent: " + a_x.out + " " + a_y.out + "%N")
			Result := a_client.send_goal (l_goal)
		end

	is_accepted (a_goal: separate ROS_GOAL_HANDLE [NAV2_MSGS_NAVIGATE_TO_POSE_FEEDBACK, NAV2_MSGS_NAVIGATE_TO_POSE_RESULT]): BOOLEAN
			-- Did the server accept `a_goal'?
		do
			Result := a_goal.is_accepted
		end

	arm (a_deadline: separate DEADLINE)
			-- Start the deadline's clock.
		do
			a_deadline.arm
		end

	disarm (a_deadline: separate DEADLINE)
			-- Drop the deadline (nothing left pending: the program can end).
		do
			a_deadline.disarm
		end

	follow (a_goal: separate ROS_GOAL_HANDLE [NAV2_MSGS_NAVIGATE_TO_POSE_FEEDBACK, NAV2_MSGS_NAVIGATE_TO_POSE_RESULT];
			a_stop: separate STOP_SIGNALER)
			-- Once the goal is over or the stop requested: cancel the goal if it is still going.
		require
			over_or_stopped: a_goal.is_done or a_stop.is_stop_requested
		do
			if not a_goal.is_done then
				print ("stop requested: cancelling the goal%N")
				a_goal.cancel
			end
		end

	report (a_goal: separate ROS_GOAL_HANDLE [NAV2_MSGS_NAVIGATE_TO_POSE_FEEDBACK, NAV2_MSGS_NAVIGATE_TO_POSE_RESULT])
			-- Once the result is there, say how the goal ended.
		require
			result_came: a_goal.has_result
		do
			if a_goal.is_succeeded then
				print ("goal reached")
			elseif a_goal.is_canceled then
				print ("goal canceled")
			else
				print ("goal ended with status " + a_goal.status.out)
			end
			if attached a_goal.feedback as l_feedback then
				print (" after " + a_goal.feedback_count.out + " feedback messages, "
					+ l_feedback.distance_remaining.out + " m remaining")
			end
			print ("%N")
		end

end
