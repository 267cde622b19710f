note
	description: "[
		One robot's work: shuttling between the two rooms, one trip per room. In each room the
		robot drives to its work point, then to its waiting point by the passage; there it
		waits (a wait condition on the shared PASSAGE_SIGNALER) until the passage is free,
		crosses it, and frees it once clear of the passage on the other side. Robot 1 keeps to
		the lower half of the rooms, robot 2 to the upper half, so that outside the passage
		their paths never meet. Uncoordinated, it crosses without asking.
	]"

class
	SHUTTLE

create
	make

feature {NONE} -- Initialization

	make (a_number: INTEGER; a_odometry: separate ODOMETRY_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE;
			a_passage: separate PASSAGE_SIGNALER; a_stop: separate STOP_SIGNALER;
			a_passage_x, a_passage_y, a_speed: REAL_64; a_coordinated: BOOLEAN)
			-- Shuttle of robot `a_number' (1: lower lane, 2: upper lane) through the passage
			-- centred on (`a_passage_x', `a_passage_y'), shared through `a_passage' when
			-- `a_coordinated'; until `a_stop' fires.
		require
			one_of_two: a_number = 1 or a_number = 2
			positive_speed: a_speed > 0.0
		do
			number := a_number
			odometry := a_odometry
			passage := a_passage
			stop := a_stop
			passage_x := a_passage_x
			passage_y := a_passage_y
			is_coordinated := a_coordinated
			if a_number = 1 then
				lane := -1.0
			else
				lane := 1.0
			end
			create pilot.make (a_odometry, a_drive, a_stop, a_speed, Period)
		end

feature -- Access

	number: INTEGER
			-- Which robot.

	crossings: INTEGER
			-- Crossings of the passage done.

	waits: INTEGER
			-- Times the passage was taken when the robot reached it.

feature -- Status report

	is_coordinated: BOOLEAN
			-- Does the robot ask for the passage?

	is_stopped: BOOLEAN
			-- Has the stop signaler fired?

feature -- Basic operations

	run
			-- Shuttle between the rooms until stopped.
		local
			side: REAL_64
		do
			from
				side := room_of (position_x (odometry))
			until
				is_stopped
			loop
				go (side * Work_offset, lane * Work_lane, Loose)
				go (side * Wait_offset, lane * Wait_lane, Loose)
				if not is_stopped and is_coordinated then
					note_if_taken (passage)
					enter_passage (passage, stop)
				end
				if not is_stopped then
					say ("crossing")
					go (side * Entrance_offset, 0.0, Tight)
					go (- side * Entrance_offset, 0.0, Tight)
					go (- side * Wait_offset, lane * Wait_lane, Loose)
					if is_coordinated then
						leave_passage (passage)
					end
					if not is_stopped then
						crossings := crossings + 1
						say ("crossed, " + crossings.out + " crossing(s)")
					end
					side := - side
				end
			end
			say ("stopped after " + crossings.out + " crossing(s), found the passage taken " + waits.out + " time(s)")
		end

feature {NONE} -- The passage

	note_if_taken (a_passage: separate PASSAGE_SIGNALER)
			-- Count a wait if the passage is taken now.
		do
			if not a_passage.is_free then
				waits := waits + 1
				say ("waiting for robot " + a_passage.holder.out)
			end
		end

	enter_passage (a_passage: separate PASSAGE_SIGNALER; a_stop: separate STOP_SIGNALER)
			-- Wait until the passage is free (or the shuttle is stopped), then take it.
		require
			free_or_stop: a_passage.is_free or a_stop.is_stop_requested
		do
			if a_stop.is_stop_requested then
				is_stopped := True
			else
				a_passage.enter (number)
			end
		end

	leave_passage (a_passage: separate PASSAGE_SIGNALER)
			-- Free the passage.
		require
			held: a_passage.holder = number
		do
			a_passage.leave (number)
		end

feature {NONE} -- Implementation

	go (a_dx, a_dy, a_tolerance: REAL_64)
			-- Drive to the point (`a_dx', `a_dy') from the passage's centre, unless stopped.
		do
			if not is_stopped then
				pilot.go_to (passage_x + a_dx, passage_y + a_dy, a_tolerance)
				is_stopped := pilot.is_cancelled
			end
		end

	room_of (a_x: REAL_64): REAL_64
			-- -1 for the room left of the passage, 1 for the right one.
		do
			if a_x < passage_x then
				Result := -1.0
			else
				Result := 1.0
			end
		end

	position_x (a_odometry: separate ODOMETRY_SIGNALER): REAL_64
			-- The robot's x once known.
		require
			located: a_odometry.has_reading
		do
			Result := a_odometry.x
		end

	say (a_text: STRING)
			-- Print `a_text' with the time and the robot.
		do
			print ("Robot " + number.out + " [" + clock.now.rounded.out + " s]: " + a_text + "%N")
		end

	clock: TIMER
			-- The runtime's clock.
		once
			create Result.make
		end

	pilot: PILOT
			-- Drives the robot.

	odometry: separate ODOMETRY_SIGNALER
			-- The robot's odometry.

	passage: separate PASSAGE_SIGNALER
	stop: separate STOP_SIGNALER
			-- Shared with the other robot.

	passage_x, passage_y: REAL_64
			-- Centre of the passage.

	lane: REAL_64
			-- -1: lower half of the rooms, 1: upper half.

feature {NONE} -- Constants (offsets from the passage's centre, m)

	Work_offset: REAL_64 = 1.5
	Work_lane: REAL_64 = 0.9
			-- Work points, one per room and lane.

	Wait_offset: REAL_64 = 0.9
	Wait_lane: REAL_64 = 0.5
			-- Where the robot waits for the passage, and where it frees it after crossing.

	Entrance_offset: REAL_64 = 0.45
			-- The passage's entrances, on its axis.

	Loose: REAL_64 = 0.06
	Tight: REAL_64 = 0.02
			-- Arrival tolerances.

	Period: INTEGER_64 = 100_000_000
			-- Nanoseconds between two steps of the pilot.

invariant
	lane: lane = -1.0 or lane = 1.0

end
