note
	description: "A camera that can be started and stopped."

class
	CAMERA

create
	make

feature {NONE} -- Initialization

	make
			-- Stopped camera.
		do
			is_on := False
		end

feature -- Status report

	is_on: BOOLEAN
			-- Is the camera streaming?

feature -- Basic operations

	start
			-- Start streaming.
		do
			is_on := True
		end

	stop
			-- Stop streaming.
		do
			is_on := False
		end

end
