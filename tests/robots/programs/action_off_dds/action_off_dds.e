note
	description: "Sends a Fibonacci goal without asking whether a server is there: off DDS, an exception says why."

class
	ACTION_OFF_DDS

create
	make

feature {NONE} -- Initialization

	make
			-- Say whether a server is there, then send a goal anyway.
		local
			client: separate ROS_ACTION_CLIENT [EXAMPLE_INTERFACES_FIBONACCI_GOAL, EXAMPLE_INTERFACES_FIBONACCI_FEEDBACK, EXAMPLE_INTERFACES_FIBONACCI_RESULT]
		do
			create client.make ("/fib", "example_interfaces/action/Fibonacci")
			send (client)
		end

feature {NONE} -- Implementation

	send (a_client: separate ROS_ACTION_CLIENT [EXAMPLE_INTERFACES_FIBONACCI_GOAL, EXAMPLE_INTERFACES_FIBONACCI_FEEDBACK, EXAMPLE_INTERFACES_FIBONACCI_RESULT])
			-- Send a goal of order 3.
		local
			l_goal: EXAMPLE_INTERFACES_FIBONACCI_GOAL
			l_handle: separate ROS_GOAL_HANDLE [EXAMPLE_INTERFACES_FIBONACCI_FEEDBACK, EXAMPLE_INTERFACES_FIBONACCI_RESULT]
		do
			print ("available " + a_client.is_available (0.1).out + "%N")
			create l_goal.make
			l_goal.set_order (3)
			l_handle := a_client.send_goal (l_goal)
			print ("sent%N")
		end

end
