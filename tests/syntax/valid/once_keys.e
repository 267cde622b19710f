note
	description: "Once routines: plain, and with the keys PROCESS, THREAD and OBJECT."

class
	ONCE_KEYS

create
	make

feature {NONE} -- Initialization

	make
			-- Call each once routine twice.
		do
			greet
			greet
			print (shared_counter.item.out + "%N")
			shared_counter.put (shared_counter.item + 1)
			print (shared_counter.item.out + "%N")
			print (per_thread.count.out + "%N")
			print (per_object.out + " " + per_object.out + "%N")
			separate configuration as cfg do
				print (cfg.item.out)
			end
			print ("%N")
			separate global_log as l_log do
				print (l_log.count.out + "%N")
			end
		end

feature -- Once routines

	greet
			-- Print a greeting, the first time only.
		once
			print ("hello once%N")
		end

	shared_counter: CELL [INTEGER]
			-- A counter shared by the whole processor.
		once
			create Result.put (0)
		ensure
			exists: Result /= Void
		end

	per_thread: STRING
			-- One string per thread.
		once ("THREAD")
			Result := "thread"
		end

	per_object: INTEGER
			-- Computed once for each object.
		once ("OBJECT")
			Result := 7 * 6
		end

	configuration: separate CELL [INTEGER]
			-- A setting shared by all processors.
		once ("PROCESS")
			create <NONE> Result.put (2_024)
		end

	global_log: separate ARRAYED_LIST [STRING]
			-- A log shared by the whole process.
		once ("process")
			create Result.make (10)
		end

end
