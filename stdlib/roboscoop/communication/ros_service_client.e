note
	description: "[
		Calls one ROS 2 service (rmw_cyclonedds_cpp's request and reply format, docs/ROBOTS.md):
		`call' sends a request object and returns the server's response, as a new object of
		RESPONSE (classes from `scoopc msg pkg/srv/Name'). A call is a query: the caller waits by
		necessity; no response within `timeout' seconds raises an exception. Needs a ROS 2 robot
		over DDS (`scoopc run --robot ros2').
	]"

class
	ROS_SERVICE_CLIENT [REQUEST -> ROS_MESSAGE, RESPONSE -> ROS_MESSAGE]

create
	make

feature {NONE} -- Initialization

	make (a_service, a_type: separate STRING)
			-- Client of the service `a_service' (a full name: "/robot1/reset") of type `a_type'
			-- ("std_srvs/srv/Trigger").
		do
			create service.make_from_separate (a_service)
			create service_type.make_from_separate (a_type)
			timeout := 10.0
		ensure
			default_timeout: timeout = 10.0
		end

feature -- Access

	service: STRING
			-- Full name of the service.

	service_type: STRING
			-- Its ROS 2 type ("std_srvs/srv/Trigger").

	timeout: REAL_64
			-- Seconds a call waits for the response.

	call_count: INTEGER
			-- Calls answered so far.

feature -- Element change

	set_timeout (a_seconds: REAL_64)
			-- Wait at most `a_seconds' for each response.
		require
			positive: a_seconds > 0.0
		do
			timeout := a_seconds
		ensure
			set: timeout = a_seconds
		end

feature -- Basic operations

	call (a_request: separate REQUEST): RESPONSE
			-- The server's response to `a_request'.
		do
			Result := call_service (a_request)
			call_count := call_count + 1
		ensure
			counted: call_count = old call_count + 1
		end

	is_available (a_seconds: REAL_64): BOOLEAN
			-- Is a server of `service' there (waiting up to `a_seconds' for one)?
		external
			"Python"
		end

feature {NONE} -- Transport

	call_service (a_request: separate ROS_MESSAGE): RESPONSE
			-- Send `a_request', wait for the response.
		external
			"Python"
		end

end
