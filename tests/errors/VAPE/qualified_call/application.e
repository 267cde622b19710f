class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Move a robot.
		do
			create robot
			create arm.make (robot)
			arm.move (2)
		end

	robot: ROBOT
			-- The robot the arm belongs to.

	arm: ARM
			-- The arm.

end
