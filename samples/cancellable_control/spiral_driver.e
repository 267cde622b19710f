note
	description: "[
		A cancellable control loop that drives a robot along a widening spiral: each step sends
		the forward speed and a turn rate that shrinks as the steps go by.
	]"

class
	SPIRAL_DRIVER

inherit
	CANCELLABLE_CONTROL_LOOP
		rename
			make as make_loop
		redefine
			step, run
		end

create
	make

feature {NONE} -- Initialization

	make (a_stop: separate STOP_SIGNALER; a_drive: separate DIFFERENTIAL_DRIVE)
			-- Driver of `a_drive' stopped by `a_stop', ten steps a second.
		do
			make_loop (a_stop, 100_000_000)
			drive := a_drive
		end

feature -- Access

	drive: separate DIFFERENTIAL_DRIVE
			-- The robot's velocity commands.

	Speed: REAL_64 = 0.1
			-- Forward speed (m/s).

feature -- Basic operations

	run
			-- <Precursor>
		do
			Precursor
			print ("Driver: stop seen after " + iteration_count.out + " steps%N")
		end

	step
			-- Send the next command of the spiral.
		do
			command (drive)
		end

feature {NONE} -- Implementation

	command (a_drive: separate DIFFERENTIAL_DRIVE)
			-- Forward at `Speed', turning ever more gently.
		do
			a_drive.send (Speed, 2.0 / (1.0 + iteration_count / 10.0))
		end

end
