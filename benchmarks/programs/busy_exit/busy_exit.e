note
	description: "[
		N processors (the first argument, default 50) each spin in a loop that makes no runtime
		call, so none of them notices a stop request; the root says `busy' once every one of
		them has told a counter (on a processor of its own) that it starts. benchmarks/exit_time.py interrupts it and times how long the run
		takes to end.
	]"

class
	BUSY_EXIT

create
	make

feature {NONE} -- Initialization

	make
			-- Start the spinners, wait until each has begun, say so.
		local
			i, count: INTEGER
			spinner: separate SPINNER
			counter: separate COUNTER
		do
			count := 50
			if (create {ARGUMENTS}).argument_count > 0 then
				count := (create {ARGUMENTS}).argument (1).to_integer
			end
			create counter
			from i := 1 until i > count loop
				create spinner.make (counter)
				start (spinner)
				i := i + 1
			end
			await (counter, count)
			print ("busy%N")
		end

feature {NONE} -- Implementation

	start (a_spinner: separate SPINNER)
			-- Let `a_spinner' spin.
		do
			a_spinner.spin
		end

	await (a_counter: separate COUNTER; a_count: INTEGER)
			-- Wait until `a_count' spinners have begun.
		require
			all_begun: a_counter.count >= a_count
		do
		end

end
