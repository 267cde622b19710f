note
	description: "[
		EiffelThread: threads sharing a counter under a MUTEX, once per thread, try_lock,
		SEMAPHORE, join_with_timeout, exit, a CONDITION_VARIABLE buffer, WORKER_THREAD.
		Every thread is joined before its results are printed.
	]"

class
	THREADS_MUTEX

create
	make

feature {NONE} -- Initialization

	make
		do
			log := "log:"
			counting
			probing
			buffering
			working
		end

feature -- Parts

	counting
		local
			counter: SHARED_COUNTER
			mutex: MUTEX
			adders: ARRAYED_LIST [ADDER]
			control: THREAD_CONTROL
		do
			create counter
			create mutex.make
			create adders.make (4)
			across 1 |..| 4 is i loop
				adders.extend (create {ADDER}.make (counter, mutex, 250 * i))
			end
			print ("launchable before: " + adders.first.is_launchable.out + "%N")
			across adders is a loop
				a.launch
			end
			print ("launchable after: " + adders.first.is_launchable.out + "%N")
			create control
			control.join_all
			print ("counter: " + counter.value.out + "%N")
			across adders is a loop
				print ("turns seen: " + a.turns_seen.out + ", terminated: " + a.terminated.out + "%N")
			end
			print ("main's own turns: " + adders.first.turns.item.out + "%N")
		end

	probing
		local
			mutex: MUTEX
			gate: SEMAPHORE
			prober: PROBER
		do
			create mutex.make
			create gate.make (0)
			create prober.make (mutex, gate)
			mutex.lock
			prober.launch
			print ("joined within 50 ms: " + prober.join_with_timeout (50).out + "%N")
			gate.post
			print ("joined within 10 s: " + prober.join_with_timeout (10_000).out + "%N")
			mutex.unlock
			print ("prober got the lock: " + prober.got_lock.out + "%N")
			print ("prober passed the gate: " + prober.passed_gate.out + "%N")
			print (prober.steps + "%N")
			print ("try_lock now: " + mutex.try_lock.out + "%N")
			mutex.unlock
			print ("semaphore try_wait: " + gate.try_wait.out + "%N")
		end

	buffering
		local
			buffer: BUFFER
			consumer: CONSUMER
			i: INTEGER
		do
			create buffer.make
			create consumer.make (buffer, 100)
			consumer.launch
			from i := 1 until i > 100 loop
				buffer.put (i)
				i := i + 1
			end
			consumer.join
			print ("sum of 1 .. 100 through the buffer: " + consumer.sum.out + "%N")
		end

	working
		local
			worker: WORKER_THREAD
		do
			create worker.make (agent record ("worker ran"))
			worker.launch
			worker.join
			print (log + "%N")
		end

feature {NONE} -- Implementation

	log: STRING

	record (s: STRING)
		do
			log.append (" " + s)
		end

end
