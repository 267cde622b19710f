note
	description: "[
		A thread system's usual shared lock: a `once ("PROCESS")' MUTEX, one object for every
		thread, while the default once (per thread) gives each thread its own.
	]"

class
	PROCESS_ONCE

create
	make

feature {NONE} -- Initialization

	make
		local
			a, b: TALLY_THREAD
		do
			create a.make (Current)
			create b.make (Current)
			a.launch
			b.launch
			a.join
			b.join
			print ("total: " + total.out + "%N")
		end

feature -- Access

	total: INTEGER

	shared_lock: MUTEX
			-- One mutex for the whole process.
		once ("PROCESS")
			create Result.make
		end

	add (n: INTEGER)
		do
			shared_lock.lock
			total := total + n
			shared_lock.unlock
		end

end
