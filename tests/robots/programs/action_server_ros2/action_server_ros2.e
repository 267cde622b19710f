note
	description: "[
		Serves the Fibonacci action /fib on a ROS 2 run (ROS_ACTION_SERVER): the first goal is
		computed, one number of feedback at a time, and succeeds; the second goal runs until a
		client asks to cancel it, then ends cancelled with what it had. Then the program ends.
	]"

class
	ACTION_SERVER_ROS2

create
	make

feature {NONE} -- Initialization

	make
			-- Serve two goals.
		local
			server: separate ROS_ACTION_SERVER [EXAMPLE_INTERFACES_FIBONACCI_GOAL, EXAMPLE_INTERFACES_FIBONACCI_FEEDBACK, EXAMPLE_INTERFACES_FIBONACCI_RESULT]
		do
			create server.make ("/fib", "example_interfaces/action/Fibonacci")
			compute (server)
			until_cancelled (server)
			close (server)
		end

feature {NONE} -- Implementation

	compute (a_server: separate ROS_ACTION_SERVER [EXAMPLE_INTERFACES_FIBONACCI_GOAL, EXAMPLE_INTERFACES_FIBONACCI_FEEDBACK, EXAMPLE_INTERFACES_FIBONACCI_RESULT])
			-- Compute the first goal's sequence, with feedback.
		require
			asked: a_server.goal_count >= 1
		local
			l_sequence: ARRAY [INTEGER_32]
			l_feedback: EXAMPLE_INTERFACES_FIBONACCI_FEEDBACK
			l_result: EXAMPLE_INTERFACES_FIBONACCI_RESULT
			i, n: INTEGER
		do
			if attached a_server.last_goal as l_goal then
				n := l_goal.goal.order
				create l_sequence.make_filled (0, 1, n + 1)
				from i := 1 until i > n + 1 loop
					if i = 2 then
						l_sequence [i] := 1
					elseif i > 2 then
						l_sequence [i] := l_sequence [i - 1] + l_sequence [i - 2]
					end
					create l_feedback.make
					l_feedback.set_sequence (l_sequence.subarray (1, i))
					l_goal.publish_feedback (l_feedback)
					i := i + 1
				end
				create l_result.make
				l_result.set_sequence (l_sequence)
				l_goal.succeed (l_result)
				print ("goal 1: order " + n.out + ", " + l_goal.feedback_count.out + " feedback%N")
			end
		end

	until_cancelled (a_server: separate ROS_ACTION_SERVER [EXAMPLE_INTERFACES_FIBONACCI_GOAL, EXAMPLE_INTERFACES_FIBONACCI_FEEDBACK, EXAMPLE_INTERFACES_FIBONACCI_RESULT])
			-- Once the second goal's cancel was requested, end it cancelled.
		require
			cancelled: a_server.goal_count >= 2 and a_server.cancel_count >= 1
		local
			l_result: EXAMPLE_INTERFACES_FIBONACCI_RESULT
		do
			if attached a_server.last_goal as l_goal and then l_goal.is_cancel_requested then
				create l_result.make
				l_goal.cancel_done (l_result)
				print ("goal 2: cancelled%N")
			end
		end

	close (a_server: separate ROS_ACTION_SERVER [EXAMPLE_INTERFACES_FIBONACCI_GOAL, EXAMPLE_INTERFACES_FIBONACCI_FEEDBACK, EXAMPLE_INTERFACES_FIBONACCI_RESULT])
			-- Stop serving.
		do
			a_server.close
		end

end
