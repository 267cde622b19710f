note
	description: "[
		Receives the messages of a topic as Eiffel message objects: ROS_SUBSCRIBER [M].`listen'
		turns each incoming message into an asynchronous call of `on_message' on the listener's
		processor (the newest message when several came meanwhile).
	]"

deferred class
	ROS_LISTENER [M -> ROS_MESSAGE]

feature -- Element change

	on_message (a_message: M)
			-- `a_message' arrived.
		deferred
		end

end
