class
	STEPPER

inherit
	EXECUTION_ENVIRONMENT

create
	make

feature

	make (t: separate TALLY)
		do
			tally := t
		end

	run (n: INTEGER)
			-- Bump the tally `n` times, 10 ms apart, one reservation each.
		do
			across 1 |..| n as i loop
				sleep (10_000_000)
				bump (tally)
			end
			print ("stepper done%N")
		end

feature {NONE}

	tally: separate TALLY

	bump (t: separate TALLY)
		do
			t.increment
		end

end
