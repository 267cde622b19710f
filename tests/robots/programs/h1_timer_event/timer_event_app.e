class
	TIMER_EVENT_APP

create
	make

feature

	make
			-- Delayed and repeated agents on the virtual clock (on another processor), cancel, an event.
		local
			w: separate TIMER_WORKER
			t: TIMER
			e: EVENT [INTEGER]
		do
			create t.make
			create w.make
			arm (w)
			t.sleep (1.1)
			report (w)
			create e.make
			e.subscribe (agent add)
			e.subscribe (agent add_twice)
			e.publish (3)
			e.publish (4)
			print ("event total " + total.out + " publishes " + e.publish_count.out + " subscribers " + e.subscriber_count.out + "%N")
		end

	arm (w: separate TIMER_WORKER)
		do
			w.arm
			print ("pending " + w.pending.out + "%N")
		end

	report (w: separate TIMER_WORKER)
		do
			w.cancel_all
			print ("after 1.1 s: " + create {STRING}.make_from_separate (w.joined) + " pending " + w.pending.out + "%N")
		end

	total: INTEGER

	add (n: INTEGER)
		do
			total := total + n
		end

	add_twice (n: INTEGER)
		do
			total := total + 2 * n
		end

end
