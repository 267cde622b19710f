note
	description: "[
		Services both ways on a ROS 2 run: calls the Trigger service /twin/trigger and prints its
		response, serves the SetBool service /svc/enable (ENABLE_SERVER) until it answered one
		request, then ends.
	]"

class
	SERVICE_ROS2

create
	make

feature {NONE} -- Initialization

	make
			-- Call, then serve once.
		local
			client: separate ROS_SERVICE_CLIENT [STD_SRVS_TRIGGER_REQUEST, STD_SRVS_TRIGGER_RESPONSE]
		do
			create server.make
			create client.make ("/twin/trigger", "std_srvs/srv/Trigger")
			ask (client)
			wait_served (server)
		end

feature {NONE} -- Implementation

	server: separate ENABLE_SERVER
			-- Offers /svc/enable.

	ask (a_client: separate ROS_SERVICE_CLIENT [STD_SRVS_TRIGGER_REQUEST, STD_SRVS_TRIGGER_RESPONSE])
			-- Call the trigger service once it is there.
		local
			answer: STRING
		do
			if a_client.is_available (60.0) then
				create answer.make_from_separate (a_client.call (create {STD_SRVS_TRIGGER_REQUEST}.make).message)
				print ("trigger: " + answer + "%N")
			else
				print ("no trigger service%N")
			end
		end

	wait_served (a_server: separate ENABLE_SERVER)
			-- Wait until `a_server' answered a request.
		require
			served: a_server.served_count >= 1
		do
			print ("served data=" + a_server.last_data.out + "%N")
			a_server.close
		end

end
