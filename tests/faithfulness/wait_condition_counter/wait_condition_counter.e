class
	WAIT_CONDITION_COUNTER

create
	make

feature

	make
			-- `report` waits until the tally, bumped by a stepper every 10 ms, reaches 3.
		local
			t: separate TALLY
			s: separate STEPPER
		do
			create t
			create s.make (t)
			launch (s)
			report (t)
		end

	launch (s: separate STEPPER)
		do
			s.run (5)
		end

	report (t: separate TALLY)
		require
			reached: t.value >= 3
		do
			print ("waited until " + t.value.out + "%N")
		end

end
