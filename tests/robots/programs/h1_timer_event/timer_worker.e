class
	TIMER_WORKER

create
	make

feature

	make
		do
			create log.make (10)
			create once_timer.make
			create ticker.make
		end

	arm
			-- One call after 0.5 s, one after 5 s, a tick every 0.2 s (cancelled by the third).
		do
			once_timer.call_after (0.5, agent remember ("once"))
			once_timer.call_after (5.0, agent remember ("never"))
			ticker.call_every (0.2, agent tick)
		end

	pending: INTEGER
		do
			Result := once_timer.pending_count + ticker.pending_count
		end

	cancel_all
		do
			once_timer.cancel
		end

	log: ARRAYED_LIST [STRING]

	once_timer, ticker: TIMER

	ticks: INTEGER

	remember (s: STRING)
		do
			log.extend (s + "@" + ((ticker.now * 10.0).rounded).out)
		end

	tick
		do
			ticks := ticks + 1
			remember ("tick")
			if ticks = 3 then
				ticker.cancel
			end
		end

	joined: STRING
		do
			create Result.make_empty
			across log as s loop
				if not Result.is_empty then
					Result.append (" ")
				end
				Result.append (s.item)
			end
		end

end
