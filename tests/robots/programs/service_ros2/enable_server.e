note
	description: "The SetBool service /svc/enable: remembers the data asked and says so."

class
	ENABLE_SERVER

inherit
	ROS_SERVICE_SERVER [STD_SRVS_SET_BOOL_REQUEST, STD_SRVS_SET_BOOL_RESPONSE]

create
	make

feature {NONE} -- Initialization

	make
			-- Serve /svc/enable.
		do
			make_server ("/svc/enable", "std_srvs/srv/SetBool")
		end

feature -- Access

	last_data: BOOLEAN
			-- The data of the last request.

feature -- Basic operations

	response (a_request: STD_SRVS_SET_BOOL_REQUEST): STD_SRVS_SET_BOOL_RESPONSE
			-- Success, and what was asked.
		do
			last_data := a_request.data
			create Result.make
			Result.set_success (True)
			Result.set_message ("enabled " + a_request.data.out)
		end

end
