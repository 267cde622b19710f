note
	description: "[
		A cancellable control loop on the simulator: a SPIRAL_DRIVER (a CANCELLABLE_CONTROL_LOOP)
		drives the Thymio along a widening spiral, ten commands a second, until its STOP_SIGNALER
		fires; a SUPERVISOR on another processor waits (a wait condition on the odometry) until
		the robot is a metre away from where it started and requests the stop. The root waits
		for the stop request, then brings the robot to rest.
	]"

class
	CANCELLABLE_CONTROL

create
	make

feature {NONE} -- Initialization

	make
			-- Start the driver and its supervisor; once the loop is over, stop the robot.
		local
			env: ROBOT_ENVIRONMENT
			robot: THYMIO_ROBOT
			stop: separate STOP_SIGNALER
			driver: separate SPIRAL_DRIVER
			supervisor: separate SUPERVISOR
		do
			create env
			create robot.make (env.namespace)
			create stop.make
			create driver.make (stop, robot.drive)
			create supervisor.make (stop, robot.odometry, 1.0)
			start_driver (driver)
			start_supervisor (supervisor)
			report (stop, robot.drive)
		end

feature {NONE} -- Implementation

	start_driver (a_driver: separate SPIRAL_DRIVER)
			-- Let `a_driver' run until stopped.
		do
			a_driver.run
		end

	start_supervisor (a_supervisor: separate SUPERVISOR)
			-- Let `a_supervisor' watch the robot.
		do
			a_supervisor.supervise
		end

	report (a_stop: separate STOP_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Once the stop is requested, bring the robot to rest and say so. (The driver's
			-- commands logged before come first: the drive serves its clients in order, and
			-- no step starts once the loop sees the stop.)
		require
			cancelled: a_stop.is_stop_requested
		do
			a_drive.stop
			print ("Robot at rest%N")
		ensure
			at_rest: a_drive.is_stopped
		end

end
