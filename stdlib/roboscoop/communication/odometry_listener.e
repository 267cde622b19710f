note
	description: "Receives nav_msgs/Odometry readings as plain values."

deferred class
	ODOMETRY_LISTENER

feature -- Basic operations

	on_odometry (a_x, a_y, a_theta, a_vx, a_vtheta, a_timestamp: REAL_64)
			-- New reading: position (m), heading (rad), forward and angular speeds, the
			-- message's stamp (s).
		deferred
		end

end
