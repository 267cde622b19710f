note
	description: "[
		A ROS 2 message: the ancestor of every message class, those of the Roboscoop library
		(communication/messages/) and those `scoopc msg' writes. ROS_PUBLISHER and
		ROS_SUBSCRIBER carry its descendants.
	]"

deferred class
	ROS_MESSAGE

feature -- Access

	ros_type: STRING
			-- The ROS 2 type name ("geometry_msgs/msg/Twist").
		deferred
		end

end
