class
	SIMPLE_CONTROLLER_APP

create
	make

feature

	make
			-- Run a SIMPLE_CONTROLLER on the Thymio topics; stop when a ground sensor sees a hole.
		local
			stop: separate STOP_SIGNALER
			range: separate RANGE_SIGNALER
			drive: separate DIFFERENTIAL_DRIVE
			controller: separate SIMPLE_CONTROLLER
		do
			create stop.make
			create range.make_thymio ("")
			create drive.make ("/cmd_vel", 0.2, 1.0)
			create controller.make (stop, range, drive, 0.1, 0.5, 50_000_000)
			launch (controller)
			await_hole (range)
			request (stop)
			report (controller)
		end

	launch (c: separate SIMPLE_CONTROLLER)
		do
			c.run
		end

	await_hole (r: separate RANGE_SIGNALER)
		require
			r.has_ground_hole
		do
		end

	request (s: separate STOP_SIGNALER)
		do
			s.request_stop
		end

	report (c: separate SIMPLE_CONTROLLER)
		require
			c.is_finished
		do
			print ("finished%N")
		end

end
