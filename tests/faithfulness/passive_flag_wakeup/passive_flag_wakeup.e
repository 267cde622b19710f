class
	PASSIVE_FLAG_WAKEUP

create
	make

feature

	make
			-- A watcher waits on a flag in a passive region; the root raises it after 50 ms.
		local
			w: separate WATCHER
		do
			create <NONE> flag
			create w.make (flag)
			watch (w)
			(create {EXECUTION_ENVIRONMENT}).sleep (50_000_000)
			raise (flag)
		end

	flag: separate FLAG

	watch (w: separate WATCHER)
		do
			w.live
		end

	raise (f: separate FLAG)
		do
			print ("raising%N")
			f.set
		end

end
