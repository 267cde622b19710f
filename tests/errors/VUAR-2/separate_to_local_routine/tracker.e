note
	description: "Follows a robot and prints where it is."

class
	TRACKER

create
	make

feature {NONE} -- Initialization

	make
			-- Create a robot and follow it.
		local
			l_robot: separate ROBOT
		do
			create l_robot.make
			follow (l_robot)
		end

feature -- Basic operations

	follow (a_robot: separate ROBOT)
			-- Print where `a_robot' is and remember it.
		do
			show_pose (a_robot.pose) -- E: VUAR(2)
			show_coordinates (a_robot.pose.x, a_robot.pose.y)
			remember (a_robot) -- E: VUAR(2)
			keep (a_robot)
		end

	show_pose (a_pose: POSE)
			-- Print `a_pose'.
		do
			print (a_pose.x)
			print (a_pose.y)
		end

	show_coordinates (a_x, a_y: REAL_64)
			-- Print the coordinates (`a_x', `a_y').
		do
			print (a_x)
			print (a_y)
		end

	remember (a_robot: ROBOT)
			-- Note that `a_robot' was seen.
		do
			print ("robot seen%N")
		end

	keep (a_robot: separate ROBOT)
			-- Keep `a_robot' as the robot followed.
		do
			followed := a_robot
		end

feature -- Access

	followed: detachable separate ROBOT
			-- The robot followed, if any.

end
