note
	description: "[
		Offers one ROS 2 service (rmw_cyclonedds_cpp's request and reply format, docs/ROBOTS.md).
		An heir gives `response'; each request arrives as a call of `answer' on the server's
		processor, in the order they come, and the response it returns is sent back. Request and
		response classes come from `scoopc msg pkg/srv/Name'. Needs a ROS 2 robot over DDS
		(`scoopc run --robot ros2').
	]"

deferred class
	ROS_SERVICE_SERVER [REQUEST -> ROS_MESSAGE, RESPONSE -> ROS_MESSAGE]

feature {NONE} -- Initialization

	make_server (a_service, a_type: separate STRING)
			-- Serve `a_service' (a full name: "/robot1/enable") of type `a_type' ("std_srvs/srv/SetBool").
		do
			create service.make_from_separate (a_service)
			create service_type.make_from_separate (a_type)
			start_serving
		end

feature -- Access

	service: STRING
			-- Full name of the service.

	service_type: STRING
			-- Its ROS 2 type.

	served_count: INTEGER
			-- Requests answered so far.

feature -- Basic operations

	response (a_request: REQUEST): RESPONSE
			-- The response to `a_request'.
		deferred
		end

	close
			-- Stop serving.
		external
			"Python"
		end

feature {NONE} -- Transport

	answer (a_request: REQUEST): RESPONSE
			-- Called on this processor for each request.
		do
			Result := response (a_request)
			served_count := served_count + 1
		end

	start_serving
			-- Offer the service on the transport.
		external
			"Python"
		end

end
