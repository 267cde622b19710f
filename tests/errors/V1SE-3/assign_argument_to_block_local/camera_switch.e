note
	description: "Switches from the front camera to another one."

class
	CAMERA_SWITCH

create
	make

feature {NONE} -- Initialization

	make
			-- Create two cameras and switch between them.
		local
			l_rear: separate CAMERA
		do
			create front_camera.make
			create l_rear.make
			switch (l_rear)
		end

feature -- Basic operations

	switch (a_camera: separate CAMERA)
			-- Stop the front camera and start `a_camera'.
		do
			separate front_camera as c do
				c.stop
				c := a_camera -- E: V1SE(3)
			end
			a_camera.start
		end

feature -- Access

	front_camera: separate CAMERA
			-- The camera at the front.

end
