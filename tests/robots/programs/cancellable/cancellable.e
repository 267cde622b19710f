class
	CANCELLABLE

create
	make

feature

	make
			-- A loop with period 100 ms stopped after 1 s; report what it did.
		local
			stop: separate STOP_SIGNALER
			loop_: separate COUNTING_LOOP
			timer: TIMER
			stopped_at: REAL_64
			count: INTEGER
		do
			create timer.make
			create stop.make
			create loop_.make (stop, 100_000_000)
			launch (loop_)
			timer.sleep (1.0)
			request (stop)
			stopped_at := timer.now
			count := finished_count (loop_)
			timer.sleep (1.0)
			report (loop_, count, stopped_at)
		end

	launch (l: separate COUNTING_LOOP)
		do
			l.run
		end

	request (s: separate STOP_SIGNALER)
		do
			s.request_stop
		end

	finished_count (l: separate COUNTING_LOOP): INTEGER
		require
			l.is_finished
		do
			Result := l.iteration_count
		end

	report (l: separate COUNTING_LOOP; a_count: INTEGER; a_stopped_at: REAL_64)
		do
			print ("iterations " + a_count.out + " " + l.iteration_count.out + " " + l.steps.out + "%N")
			print ("after_stop " + (l.last_step_at > a_stopped_at).out + "%N")
			print ("elapsed " + (a_stopped_at - l.first_step_at).out + "%N")
		end

end
