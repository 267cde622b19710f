note
	description: "[
		A controller of the rate benchmark: `run' repeats `step' (reserve the stop signaler, the
		odometry signaler and the drive; wait until no stop is requested and the odometry count
		is sane; send one command) `warmup' times untimed, then for `duration' seconds of the
		runtime's clock, without pausing. The time counted ends once the drive has executed every
		command (a query on it waits for the commands logged before).
	]"

class
	RATE_CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_id: INTEGER; a_stop: separate STOP_SIGNALER; a_odometry: separate ODOMETRY_SIGNALER;
			a_drive: separate DIFFERENTIAL_DRIVE; a_warmup: INTEGER; a_duration: REAL_64)
			-- Controller number `a_id' over the given signalers and drive.
		require
			warmup_not_negative: a_warmup >= 0
			positive_duration: a_duration > 0.0
		do
			id := a_id
			stop := a_stop
			odometry := a_odometry
			drive := a_drive
			warmup := a_warmup
			duration := a_duration
			create clock.make
		ensure
			id_set: id = a_id
		end

feature -- Access

	id: INTEGER
			-- Number of this controller.

	warmup: INTEGER
			-- Untimed iterations run first.

	duration: REAL_64
			-- Seconds of timed iterations.

	iteration_count: INTEGER
			-- Timed iterations done.

	seconds: REAL_64
			-- Seconds the timed iterations took, their commands all published.

	is_finished: BOOLEAN
			-- Has `run' ended?

feature -- Basic operations

	run
			-- Warm up, then iterate for `duration' seconds, as fast as it goes.
		local
			l_start, l_end: REAL_64
			l_sent: INTEGER
		do
			from
			until
				iteration_count = warmup
			loop
				step (stop, odometry, drive)
			end
			l_sent := sent_count (drive)		-- every warm-up command published
			iteration_count := 0
			l_start := clock.now
			l_end := l_start + duration
			from
			until
				clock.now >= l_end
			loop
				step (stop, odometry, drive)
			end
			l_sent := sent_count (drive)
			seconds := clock.now - l_start
			is_finished := True
		ensure
			finished: is_finished
		end

feature {NONE} -- Implementation

	stop: separate STOP_SIGNALER
	odometry: separate ODOMETRY_SIGNALER
	drive: separate DIFFERENTIAL_DRIVE
			-- The signalers and the drive of every iteration.

	clock: TIMER
			-- The runtime's clock.

	sent_count (a_drive: separate DIFFERENTIAL_DRIVE): INTEGER
			-- Commands `a_drive' has published so far.
		do
			Result := a_drive.command_count
		end

	step (a_stop: separate STOP_SIGNALER; a_odometry: separate ODOMETRY_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- One iteration: a command once the wait condition holds.
		require
			go: not a_stop.is_stop_requested and a_odometry.update_count >= 0
		do
			a_drive.send (0.1, 0.05 * id)
			iteration_count := iteration_count + 1
		end

end
